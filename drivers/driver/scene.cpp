// Scene file parsing and validation (toml++). Every key is read through a TableReader, which
// records the keys a table may have, type-checks and range-checks values, and rejects any key
// it was not asked about. Messages name the key with its table, the value and the valid range.
#include "driver/scene.hpp"

#include "driver/effect_selection.hpp"
#include "driver/model_registry.hpp"
#include "driver/particle_fill.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <sstream>

namespace epac {
namespace driver {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Physical ranges of scene values. Outside them a run does not fail with a named error but
// diverges or overflows (a radius of 1e-300 m makes a zero mass, gravity 1e300 an infinite
// velocity), so they are refused on input. Each is wide against practice; the radius and
// density bounds also keep the mass and moment of inertia normal numbers in float
// (0.4 x 4/3 pi x 0.1 kg/m^3 x (1e-7 m)^5 = 1.7e-36 > 1.2e-38).
struct PhysicalRange {
  double lo, hi;
  const char* note;
};
constexpr PhysicalRange kRadius{1e-7, 1e2, "m; 0.1 um to 100 m"};
constexpr PhysicalRange kDensity{0.1, 1e5, "kg/m^3; aerogels are about 1, osmium 22590"};
constexpr PhysicalRange kYoungsModulus{1e3, 1e13, "Pa; soft gels to above diamond"};
constexpr PhysicalRange kCoordinate{-1e6, 1e6, "m"};
constexpr PhysicalRange kSpeed{-1e4, 1e4, "m/s per component"};
constexpr PhysicalRange kSpin{-1e9, 1e9, "rad/s per component"};
constexpr PhysicalRange kGravity{-1e5, 1e5, "m/s^2 per component, 1e4 g"};

std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a float";
    case toml::node_type::boolean:
      return "a boolean";
    default:
      return "a date/time";
  }
}

std::string line_of(const toml::node& n) {
  const auto& b = n.source().begin;
  return b.line > 0 ? " [line " + std::to_string(b.line) + "]" : "";
}

// Number of a node that must be a number (integer or float). Throws naming `where`.
double as_number(const toml::node& n, const std::string& where) {
  if (auto i = n.as_integer()) return static_cast<double>(i->get());
  if (auto f = n.as_floating_point()) return f->get();
  throw SceneError(where + " must be a number, got " + type_name(n) + line_of(n));
}

class TableReader {
 public:
  // path: "" for the root, else the table's dotted name ("materials.glass", "particles.list[2]").
  TableReader(const toml::table& t, std::string path) : t_(t), path_(std::move(path)) {}

  std::string key_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

  const toml::node* get(const std::string& key) {
    allowed_.insert(key);
    return t_.get(key);
  }
  bool has(const std::string& key) { return get(key) != nullptr; }

  // A number in the range; `def` when absent (required when def is empty).
  double number(const std::string& key, double lo, Bound lk, double hi, Bound hk, std::optional<double> def,
                bool allow_inf = false) {
    const toml::node* n = get(key);
    if (!n) {
      if (def) return *def;
      throw SceneError(key_path(key) + " is missing (required; valid range " + range_text(lo, lk, hi, hk) + ")");
    }
    const double v = as_number(*n, key_path(key));
    check(key_path(key), v, lo, lk, hi, hk, allow_inf, *n);
    return v;
  }
  // A number in a physical range (closed); `def` when absent (required when def is empty).
  double number(const std::string& key, const PhysicalRange& range, std::optional<double> def) {
    const toml::node* n = get(key);
    if (!n) {
      if (def) return *def;
      throw SceneError(key_path(key) + " is missing (required; valid range " +
                       range_text(range.lo, Bound::closed, range.hi, Bound::closed) + " " + range.note + ")");
    }
    const double v = as_number(*n, key_path(key));
    check(key_path(key), v, range, *n);
    return v;
  }
  // A number read without a range check (the caller validates it, e.g. Material::validate).
  std::optional<double> raw_number(const std::string& key) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    return as_number(*n, key_path(key));
  }

  std::int64_t integer(const std::string& key, std::int64_t lo, std::int64_t hi, std::optional<std::int64_t> def) {
    const toml::node* n = get(key);
    if (!n) {
      if (def) return *def;
      throw SceneError(key_path(key) + " is missing (required; an integer in [" + std::to_string(lo) + ", " +
                       std::to_string(hi) + "])");
    }
    auto i = n->as_integer();
    if (!i) throw SceneError(key_path(key) + " must be an integer, got " + type_name(*n) + line_of(*n));
    const std::int64_t v = i->get();
    if (v < lo || v > hi)
      throw SceneError(key_path(key) + " = " + std::to_string(v) + " is outside the valid range [" +
                       std::to_string(lo) + ", " + std::to_string(hi) + "]" + line_of(*n));
    return v;
  }

  bool boolean(const std::string& key, bool def) {
    const toml::node* n = get(key);
    if (!n) return def;
    auto b = n->as_boolean();
    if (!b) throw SceneError(key_path(key) + " must be true or false, got " + type_name(*n) + line_of(*n));
    return b->get();
  }

  std::optional<std::string> string(const std::string& key) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    auto s = n->as_string();
    if (!s) throw SceneError(key_path(key) + " must be a string, got " + type_name(*n) + line_of(*n));
    return s->get();
  }

  // Three finite numbers, each in `range` when given; `def` when absent (required when def is empty).
  Vec3d vec3(const std::string& key, std::optional<Vec3d> def, const PhysicalRange* range = nullptr) {
    const toml::node* n = get(key);
    if (!n) {
      if (def) return *def;
      throw SceneError(key_path(key) + " is missing (required; three finite numbers [x, y, z])");
    }
    return vec3_of(*n, key_path(key), range);
  }

  const toml::table* table(const std::string& key) {
    const toml::node* n = get(key);
    if (!n) return nullptr;
    if (!n->is_table()) throw SceneError(key_path(key) + " must be a table, got " + type_name(*n) + line_of(*n));
    return n->as_table();
  }
  const toml::array* array(const std::string& key) {
    const toml::node* n = get(key);
    if (!n) return nullptr;
    if (!n->is_array()) throw SceneError(key_path(key) + " must be an array, got " + type_name(*n) + line_of(*n));
    return n->as_array();
  }

  // Rejects every key nobody asked for.
  void finish() const {
    for (auto&& [k, v] : t_) {
      const std::string key(k.str());
      if (allowed_.count(key)) continue;
      std::string valid;
      for (const auto& a : allowed_) valid += (valid.empty() ? "" : ", ") + a;
      throw SceneError("unknown key '" + key + "' in " +
                       (path_.empty() ? std::string("the top level") : "[" + path_ + "]") + line_of(v) +
                       " (valid keys: " + valid + ")");
    }
  }

  static std::string range_text(double lo, Bound lk, double hi, Bound hk) {
    std::ostringstream s;
    s << (lk == Bound::open ? "(" : "[") << lo << ", ";
    if (std::isinf(hi))
      s << "inf)";
    else
      s << hi << (hk == Bound::open ? ")" : "]");
    return s.str();
  }

  static void check(const std::string& name, double v, double lo, Bound lk, double hi, Bound hk, bool allow_inf,
                    const toml::node& n) {
    try {
      require_range(name, v, lo, lk, hi, hk, allow_inf);
    } catch (const ParameterError& e) { throw SceneError(e.what() + line_of(n)); }
  }
  static void check(const std::string& name, double v, const PhysicalRange& r, const toml::node& n) {
    try {
      require_range(name, v, r.lo, Bound::closed, r.hi, Bound::closed);
    } catch (const ParameterError& e) { throw SceneError(e.what() + std::string(" (") + r.note + ")" + line_of(n)); }
  }

  static Vec3d vec3_of(const toml::node& n, const std::string& where, const PhysicalRange* range = nullptr) {
    auto a = n.as_array();
    if (!a || a->size() != 3)
      throw SceneError(where + " must be an array of three numbers [x, y, z], got " +
                       (a ? "an array of " + std::to_string(a->size()) : type_name(n)) + line_of(n));
    Vec3d v{};
    for (int d = 0; d < 3; ++d) {
      const std::string w = where + "[" + std::to_string(d) + "]";
      v[d] = as_number(*a->get(d), w);
      if (range)
        check(w, v[d], *range, *a->get(d));
      else
        check(w, v[d], -kInf, Bound::open, kInf, Bound::open, false, *a->get(d));
    }
    return v;
  }

 private:
  const toml::table& t_;
  std::string path_;
  std::set<std::string> allowed_;
};

// Index of a material named by `key` in `r`.
int material_of(TableReader& r, const std::string& key, const Scene& s) {
  auto name = r.string(key);
  if (!name) throw SceneError(r.key_path(key) + " is missing (required; the name of a [materials.NAME] table)");
  auto it = s.material_index.find(*name);
  if (it == s.material_index.end()) {
    std::string known;
    for (const auto& m : s.materials) known += (known.empty() ? "" : ", ") + m.name;
    throw SceneError(r.key_path(key) + " = \"" + *name + "\" is not a material (valid: " + known + ")");
  }
  return it->second;
}

void parse_materials(TableReader& top, Scene& s) {
  const toml::table* mt = top.table("materials");
  if (!mt || mt->empty()) throw SceneError("materials is missing (required: at least one [materials.NAME] table)");
  for (auto&& [k, node] : *mt) {
    const std::string name(k.str());
    const std::string path = "materials." + name;
    if (!node.is_table()) throw SceneError(path + " must be a table, got " + type_name(node) + line_of(node));
    TableReader r(*node.as_table(), path);
    Material m;
    m.name = name;
    m.rigid = r.boolean("rigid", false);
    auto read = [&](const char* key, double& field, bool required) {
      if (auto v = r.raw_number(key))
        field = *v;
      else if (required)
        throw SceneError(path + "." + key + " is missing (required for a non-rigid material; valid range (0, inf))");
    };
    read("youngs_modulus", m.youngs_modulus, !m.rigid);
    read("poisson_ratio", m.poisson_ratio, false);
    read("density", m.density, !m.rigid);
    read("restitution", m.restitution, false);
    read("friction", m.friction, false);
    read("surface_energy", m.surface_energy, false);
    read("yield_stress", m.yield_stress, false);
    read("rolling_stiffness", m.rolling_stiffness, false);
    read("rolling_damping", m.rolling_damping, false);
    read("rolling_friction", m.rolling_friction, false);
    r.finish();
    // Material::validate owns the ranges; its messages say "material 'NAME': key", which we
    // rewrite to the scene's dotted key.
    try {
      m.validate();
    } catch (const ParameterError& e) {
      std::string msg = e.what();
      const std::string prefix = "material '" + name + "': ";
      std::string where = line_of(node);
      if (msg.compare(0, prefix.size(), prefix) == 0) {
        const std::string rest = msg.substr(prefix.size());
        msg = path + "." + rest;
        if (const toml::node* key = node.as_table()->get(rest.substr(0, rest.find(' ')))) where = line_of(*key);
      }
      throw SceneError(msg + where);
    }
    // Physical ranges of what Material::validate only requires positive (a given density of a
    // rigid material too: rigid particles are moved by it).
    const toml::table& mt_node = *node.as_table();
    if (const toml::node* d = mt_node.get("density")) TableReader::check(path + ".density", m.density, kDensity, *d);
    if (const toml::node* e = mt_node.get("youngs_modulus"); e && !m.rigid)
      TableReader::check(path + ".youngs_modulus", m.youngs_modulus, kYoungsModulus, *e);
    s.material_index[name] = static_cast<int>(s.materials.size());
    s.materials.push_back(m);
  }
}

void parse_model(TableReader& top, Scene& s) {
  static const toml::table empty;
  const toml::table* mt = top.table("model");
  TableReader r(mt ? *mt : empty, "model");
  s.model.name = r.string("name").value_or("hertz_mindlin");
  const ModelEntry& entry = find_model(s.model.name);
  for (const auto& k : entry.keys) {
    if (!k.choices.empty()) {  // a string from k.choices, stored as its index
      std::string valid;
      for (const auto& c : k.choices) valid += (valid.empty() ? "\"" : ", \"") + c + "\"";
      double index = k.default_value;
      if (const toml::node* n = r.get(k.name)) {
        auto str = n->as_string();
        if (!str)
          throw SceneError(r.key_path(k.name) + " must be a string (valid: " + valid + "), got " + type_name(*n) +
                           line_of(*n));
        auto it = std::find(k.choices.begin(), k.choices.end(), str->get());
        if (it == k.choices.end())
          throw SceneError(r.key_path(k.name) + " = \"" + str->get() + "\" is not valid (valid: " + valid + ")" +
                           line_of(*n));
        index = static_cast<double>(it - k.choices.begin());
      }
      s.model.params[k.name] = index;
      continue;
    }
    s.model.params[k.name] = r.number(k.name, k.lo, k.lo_kind, k.hi, k.hi_kind,
                                      k.has_default ? std::optional<double>(k.default_value) : std::nullopt);
  }
  if (const toml::array* eff = r.array("effects")) {
    s.model.effects_overridden = true;
    unsigned bits = 0;
    for (std::size_t e = 0; e < eff->size(); ++e) {
      const toml::node& n = *eff->get(e);
      const std::string where = "model.effects[" + std::to_string(e) + "]";
      auto str = n.as_string();
      if (!str) throw SceneError(where + " must be a string, got " + type_name(n) + line_of(n));
      const unsigned b = effect_bit(str->get());
      if (b == 0)
        throw SceneError(where + " = \"" + str->get() + "\" is not an effect (valid: " + effect_names(kAllEffects) +
                         ")" + line_of(n));
      if (!(b & entry.supported_effects))
        throw SceneError(where + " = \"" + str->get() + "\" is not implemented by model " + entry.name +
                         " (valid: " + effect_names(entry.supported_effects) + ")" + line_of(n));
      bits |= b;
    }
    s.model.effects = bits | entry.implied_effects;
  }
  r.finish();
}

// `motion = [{duration, velocity}, ...]` of a wall or a driven particle; empty if absent.
std::vector<MotionSegment> parse_motion(TableReader& r, const std::string& path, const toml::node& n) {
  std::vector<MotionSegment> out;
  const toml::array* motion = r.array("motion");
  if (!motion) return out;
  for (std::size_t m = 0; m < motion->size(); ++m) {
    const std::string mp = path + ".motion[" + std::to_string(m) + "]";
    const toml::node& mn = *motion->get(m);
    if (!mn.is_table())
      throw SceneError(mp + " must be a table {duration = .., velocity = [..]}, got " + type_name(mn) + line_of(mn));
    TableReader sr(*mn.as_table(), mp);
    MotionSegment seg;
    seg.duration = sr.number("duration", 0.0, Bound::open, kInf, Bound::open, std::nullopt);
    seg.velocity = sr.vec3("velocity", std::nullopt, &kSpeed);
    sr.finish();
    out.push_back(seg);
  }
  if (out.empty()) throw SceneError(path + ".motion is empty (give at least one {duration, velocity})" + line_of(n));
  return out;
}

ParticleSpec parse_particle(const toml::table& t, const std::string& path, const Scene& s) {
  TableReader r(t, path);
  ParticleSpec p;
  p.origin = path;
  p.position = r.vec3("position", std::nullopt, &kCoordinate);
  p.radius = r.number("radius", kRadius, std::nullopt);
  p.material = material_of(r, "material", s);
  const bool has_velocity = r.has("velocity");
  p.velocity = r.vec3("velocity", Vec3d{0, 0, 0}, &kSpeed);
  p.angular_velocity = r.vec3("angular_velocity", Vec3d{0, 0, 0}, &kSpin);
  p.driven = r.boolean("driven", false);
  p.motion = parse_motion(r, path, t);
  if (!p.motion.empty()) {
    if (!p.driven) throw SceneError(path + ".motion needs driven = true (a prescribed displacement)" + line_of(t));
    if (has_velocity) throw SceneError(path + ": give either velocity or motion, not both" + line_of(t));
    p.velocity = p.motion.front().velocity;
  }
  r.finish();
  return p;
}

void parse_particles(TableReader& top, Scene& s) {
  const toml::table* pt = top.table("particles");
  if (!pt) throw SceneError("particles is missing (required: [[particles.list]] entries and/or [particles.fill])");
  TableReader r(*pt, "particles");
  s.allow_overlap = r.boolean("allow_overlap", false);
  const std::string order = r.string("order").value_or("as_built");
  if (order != "as_built" && order != "shuffled")
    throw SceneError("particles.order = \"" + order + "\" is not a particle order (valid: \"as_built\", \"shuffled\")");
  s.shuffle = order == "shuffled";
  s.order_seed = static_cast<std::uint64_t>(r.integer("order_seed", 0, std::numeric_limits<std::int64_t>::max(), 1));
  if (const toml::array* list = r.array("list")) {
    for (std::size_t k = 0; k < list->size(); ++k) {
      const std::string path = "particles.list[" + std::to_string(k) + "]";
      const toml::node& n = *list->get(k);
      if (!n.is_table()) throw SceneError(path + " must be a table, got " + type_name(n) + line_of(n));
      s.particles.push_back(parse_particle(*n.as_table(), path, s));
    }
  }
  if (const toml::table* ft = r.table("fill")) {
    TableReader f(*ft, "particles.fill");
    FillSpec& fill = s.fill;
    fill.enabled = true;
    fill.box_min = f.vec3("box_min", std::nullopt, &kCoordinate);
    fill.box_max = f.vec3("box_max", std::nullopt, &kCoordinate);
    fill.count = f.integer("count", 0, 100000000, std::nullopt);
    fill.radius_min = f.number("radius_min", kRadius, std::nullopt);
    fill.radius_max =
        f.number("radius_max", fill.radius_min, Bound::closed, kRadius.hi, Bound::closed, fill.radius_min);
    fill.material = material_of(f, "material", s);
    fill.seed = static_cast<std::uint64_t>(f.integer("seed", 0, std::numeric_limits<std::int64_t>::max(), 1));
    fill.velocity = f.vec3("velocity", Vec3d{0, 0, 0}, &kSpeed);
    f.finish();
  }
  if (const toml::table* lt = r.table("lattice")) {
    TableReader l(*lt, "particles.lattice");
    LatticeSpec& lat = s.lattice;
    lat.enabled = true;
    const std::string type = l.string("type").value_or("fcc");
    if (type != "fcc")
      throw SceneError("particles.lattice.type = \"" + type + "\" is not valid (valid: \"fcc\")" + line_of(*lt));
    lat.a = l.number("a", 0.0, Bound::open, kCoordinate.hi, Bound::closed, std::nullopt);
    const toml::array* cells = l.array("cells");
    if (!cells || cells->size() != 3)
      throw SceneError(std::string("particles.lattice.cells ") +
                       (cells ? "must be an array of three integers [nx, ny, nz]"
                              : "is missing (required; three integers [nx, ny, nz] >= 1)") +
                       line_of(*lt));
    for (int d = 0; d < 3; ++d) {
      const toml::node& n = *cells->get(d);
      const std::string w = "particles.lattice.cells[" + std::to_string(d) + "]";
      auto i = n.as_integer();
      if (!i) throw SceneError(w + " must be an integer, got " + type_name(n) + line_of(n));
      if (i->get() < 1 || i->get() > 100000)
        throw SceneError(w + " = " + std::to_string(i->get()) + " is outside the valid range [1, 100000]" + line_of(n));
      lat.cells[d] = i->get();
    }
    if (lat.count() > 100000000)
      throw SceneError("particles.lattice.cells gives " + std::to_string(lat.count()) +
                       " particles, outside the valid range [4, 100000000]" + line_of(*lt));
    lat.origin = l.vec3("origin", s.box.enabled ? s.box.lo : Vec3d{0, 0, 0}, &kCoordinate);
    lat.radius_min = l.number("radius_min", kRadius, std::nullopt);
    lat.radius_max = l.number("radius_max", lat.radius_min, Bound::closed, kRadius.hi, Bound::closed, lat.radius_min);
    lat.material = material_of(l, "material", s);
    lat.seed = static_cast<std::uint64_t>(l.integer("seed", 0, std::numeric_limits<std::int64_t>::max(), 1));
    lat.jitter = l.number("jitter", 0.0, Bound::closed, kCoordinate.hi, Bound::closed, 0.0);
    lat.velocity = l.vec3("velocity", Vec3d{0, 0, 0}, &kSpeed);
    l.finish();
  }
  r.finish();
}

void parse_box(TableReader& top, Scene& s) {
  const toml::table* bt = top.table("box");
  if (!bt) return;
  TableReader r(*bt, "box");
  BoxSpec& b = s.box;
  b.enabled = true;
  b.lo = r.vec3("lo", std::nullopt, &kCoordinate);
  b.hi = r.vec3("hi", std::nullopt, &kCoordinate);
  for (int d = 0; d < 3; ++d)
    if (!(b.hi[d] > b.lo[d])) {
      std::ostringstream m;
      m << "box.hi[" << d << "] = " << b.hi[d] << " is outside the valid range (box.lo[" << d << "] = " << b.lo[d]
        << ", inf)" << line_of(*bt);
      throw SceneError(m.str());
    }
  if (const toml::array* per = r.array("periodic")) {
    if (per->size() != 3)
      throw SceneError("box.periodic must be an array of three booleans [x, y, z], got an array of " +
                       std::to_string(per->size()) + line_of(*bt));
    for (int d = 0; d < 3; ++d) {
      const toml::node& n = *per->get(d);
      auto v = n.as_boolean();
      if (!v)
        throw SceneError("box.periodic[" + std::to_string(d) + "] must be true or false, got " + type_name(n) +
                         line_of(n));
      b.periodic[d] = v->get();
    }
  }
  if (const toml::table* dt = r.table("deform")) {
    TableReader dr(*dt, "box.deform");
    b.deform = true;
    b.scale = dr.vec3("scale", std::nullopt);
    b.deform_steps = dr.integer("steps", 1, 1000000000000LL, std::nullopt);
    dr.finish();
    static const char* axis = "xyz";
    for (int d = 0; d < 3; ++d) {
      std::ostringstream m;
      if (!(b.scale[d] > 0.0)) {
        m << "box.deform.scale[" << d << "] = " << b.scale[d] << " is outside the valid range (0, inf)" << line_of(*dt);
        throw SceneError(m.str());
      }
      if (b.scale[d] != 1.0 && !b.periodic[d]) {
        m << "box.deform.scale[" << d << "] = " << b.scale[d] << " deforms the non-periodic axis " << axis[d]
          << " (box.periodic[" << d << "] = false); valid: 1 on non-periodic axes (deform only periodic axes)"
          << line_of(*dt);
        throw SceneError(m.str());
      }
    }
  }
  r.finish();
}

void parse_walls(TableReader& top, Scene& s) {
  const toml::array* wa = top.array("walls");
  if (!wa) return;
  for (std::size_t k = 0; k < wa->size(); ++k) {
    const std::string path = "walls[" + std::to_string(k) + "]";
    const toml::node& n = *wa->get(k);
    if (!n.is_table()) throw SceneError(path + " must be a table ([[walls]]), got " + type_name(n) + line_of(n));
    TableReader r(*n.as_table(), path);
    WallSpec w;
    w.name = r.string("name").value_or("wall" + std::to_string(k));
    w.point = r.vec3("point", std::nullopt, &kCoordinate);
    const Vec3d nrm = r.vec3("normal", std::nullopt);
    const double len = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    if (!(len > 0.0) || !std::isfinite(len)) {
      std::ostringstream m;
      m << path << ".normal = [" << nrm[0] << ", " << nrm[1] << ", " << nrm[2] << "] has length " << len
        << ", outside the valid range (0, inf)" << line_of(n);
      throw SceneError(m.str());
    }
    for (int d = 0; d < 3; ++d) w.normal[d] = nrm[d] / len;
    w.material = material_of(r, "material", s);
    const bool has_velocity = r.has("velocity");
    w.velocity = r.vec3("velocity", Vec3d{0, 0, 0}, &kSpeed);
    w.segments = parse_motion(r, path, n);
    if (!w.segments.empty() && has_velocity)
      throw SceneError(path + ": give either velocity or motion, not both" + line_of(n));
    r.finish();
    s.walls.push_back(w);
  }
}

void parse_run(TableReader& top, Scene& s) {
  const toml::table* rt = top.table("run");
  if (!rt) throw SceneError("run is missing (required: [run] with dt and steps)");
  TableReader r(*rt, "run");
  s.run.dt = r.number("dt", 0.0, Bound::open, kInf, Bound::open, std::nullopt);
  s.run.steps = r.integer("steps", 0, 1000000000000LL, std::nullopt);
  s.run.output_interval = r.integer("output_interval", 1, 1000000000000LL, std::int64_t(0));
  s.run.skin = r.number("skin", 0.0, Bound::closed, kInf, Bound::open, -1.0);
  s.run.contact_output = r.boolean("contact_output", false);
  s.run.particle_output = r.boolean("particle_output", false);
  if (const toml::node* n = r.get("spatial_sort")) {
    if (auto b = n->as_boolean()) {
      s.run.spatial_sort = b->get() ? RunSpec::Sort::always : RunSpec::Sort::never;
    } else if (auto str = n->as_string(); str && str->get() == "auto") {
      s.run.spatial_sort = RunSpec::Sort::automatic;
    } else {
      throw SceneError(std::string("run.spatial_sort must be \"auto\", true (every rebuild) or false (never), got ") +
                       (n->as_string() ? "\"" + n->as_string()->get() + "\"" : type_name(*n)) + line_of(*n));
    }
  }
  s.run.sort_interval = r.integer("sort_interval", 1, 1000000000000LL, std::int64_t(1000));
  s.run.deterministic = r.boolean("deterministic", false);
  s.run.snapshot_format = r.string("snapshot_format").value_or("none");
  if (s.run.snapshot_format != "none" && s.run.snapshot_format != "vtp")
    throw SceneError("run.snapshot_format = \"" + s.run.snapshot_format +
                     "\" is not a snapshot format (valid: \"none\", \"vtp\")");
  s.run.initial_history = r.string("initial_history").value_or("from_overlaps");
  if (s.run.initial_history != "from_overlaps" && s.run.initial_history != "zero")
    throw SceneError("run.initial_history = \"" + s.run.initial_history +
                     "\" is not a history start (valid: \"from_overlaps\", \"zero\")");
  r.finish();
}

// Walls only bound non-periodic axes: a plane with a normal component along a periodic axis
// would cut the box where the particles' images continue.
void check_walls_in_box(const Scene& s) {
  if (!s.box.enabled) return;
  static const char* axis = "xyz";
  for (std::size_t k = 0; k < s.walls.size(); ++k)
    for (int d = 0; d < 3; ++d)
      if (s.box.periodic[d] && s.walls[k].normal[d] != 0.0) {
        const Vec3d& n = s.walls[k].normal;
        std::ostringstream m;
        m << "walls[" << k << "].normal = [" << n[0] << ", " << n[1] << ", " << n[2]
          << "] (normalised) has a component "
          << "along the periodic axis " << axis[d] << " (box.periodic[" << d << "] = true); valid: normal[" << d
          << "] = 0 (walls only on non-periodic axes)";
        throw SceneError(m.str());
      }
}

// The minimum image is the right one, and the cell list finds each pair once, while every
// interaction distance (2 R_max + skin; MDR radius growth: R_max x radius_cap) stays below half
// of every periodic edge, the smallest one a deformation reaches included.
void check_periodic_lengths(const Scene& s) {
  if (!s.box.enabled || !s.box.any_periodic()) return;
  double rmax = s.max_radius();
  if (s.model.name == "mdr" && (s.model.effects & kRadiusGrowth)) rmax *= s.model.params.at("radius_cap");
  const double reach = 2.0 * rmax + s.run.skin;
  static const char* axis = "xyz";
  for (int d = 0; d < 3; ++d) {
    if (!s.box.periodic[d]) continue;
    const double L = s.box.min_edge(d);
    if (L < 2.0 * reach) {
      std::ostringstream m;
      m << "box: the periodic edge along " << axis[d] << " (box.hi[" << d << "] - box.lo[" << d << "]"
        << (s.box.deform ? " x min(1, box.deform.scale[" + std::to_string(d) + "])" : std::string()) << ") = " << L
        << " m is outside the valid range [2 x (2 R_max + skin) = " << 2.0 * reach << " m, inf) (R_max = " << rmax
        << " m" << (s.model.name == "mdr" && (s.model.effects & kRadiusGrowth) ? " incl. model.radius_cap" : "")
        << ", run.skin = " << s.run.skin << " m): the minimum image would be ambiguous";
      throw SceneError(m.str());
    }
  }
}

// Cross-checks after every table is read, then the derived quantities.
void finish_scene(Scene& s) {
  std::set<int> pm, wm;
  for (const auto& p : s.particles) pm.insert(p.material);
  if (s.fill.enabled && s.fill.count > 0) pm.insert(s.fill.material);
  if (s.lattice.enabled) pm.insert(s.lattice.material);
  for (const auto& w : s.walls) wm.insert(w.material);
  if (pm.empty() && !s.fill.enabled)
    throw SceneError(
        "particles: no particles (give [[particles.list]] entries, [particles.fill] or [particles.lattice])");
  for (int m : pm) {
    const Material& mat = s.materials[m];
    if (!(mat.density > 0.0) || !std::isfinite(mat.density))
      throw SceneError("materials." + mat.name + ".density = " + std::to_string(mat.density) +
                       " is outside the valid range (0, inf) (particles are made of it)");
  }
  // Two rigid bodies that can meet have no contact law.
  for (int a : pm) {
    for (int b : pm)
      if (s.materials[a].rigid && s.materials[b].rigid)
        throw SceneError("materials." + s.materials[a].name + " and materials." + s.materials[b].name +
                         " are both rigid and both particle materials: two rigid bodies cannot be in contact");
    for (int b : wm)
      if (s.materials[a].rigid && s.materials[b].rigid)
        throw SceneError("materials." + s.materials[a].name + " (particles) and materials." + s.materials[b].name +
                         " (walls) are both rigid: two rigid bodies cannot be in contact");
  }

  const bool periodic = s.box.enabled && s.box.any_periodic();
  if (periodic) wrap_into_box(s.box, s.particles);  // the listed particles, before the fill avoids them
  if (!s.allow_overlap && !periodic) check_no_overlap(s.particles);
  fill_box(s.fill, s.particles);
  fill_lattice(s.lattice, s.particles);
  if (periodic) wrap_into_box(s.box, s.particles);
  if (s.shuffle) shuffle_order(s.order_seed, s.particles);
  // Periodic: one check over everything, images across the faces included. A lattice next to
  // other particles: the lattice itself does not avoid them.
  if (!s.allow_overlap && (periodic || s.lattice.enabled)) check_no_overlap(s.particles, periodic ? &s.box : nullptr);
  if (s.particles.empty()) throw SceneError("particles: no particles (particles.fill.count = 0 and no list)");
  check_walls_in_box(s);

  if (s.run.output_interval == 0) s.run.output_interval = std::max<std::int64_t>(1, s.run.steps / 100);

  const ModelEntry& entry = find_model(s.model.name);
  s.model.derived_effects =
      derive_effects(s.materials, std::vector<int>(pm.begin(), pm.end()), std::vector<int>(wm.begin(), wm.end()));
  if (!s.model.effects_overridden) {
    unsigned bits = s.model.derived_effects | entry.implied_effects;
    if ((bits & kRolling) && !(bits & kFriction)) {
      bits |= kFriction;  // rolling is compiled with friction; mu = 0 gives no tangential force
      s.model.notes.push_back("rolling resistance without sliding friction: the friction effect is on with mu = 0");
    }
    if (bits & kPlasticity) bits |= entry.implied_with_plasticity;
    // MDR Part II: the bulk response is compiled in where the scene asks for it
    if (s.model.name == "mdr" && s.model.params.at("psi_b") > 0.0) bits |= kBulkResponse;
    s.model.effects = bits & entry.supported_effects;
    const unsigned ignored = s.model.derived_effects & ~entry.supported_effects;
    if (ignored)
      s.model.notes.push_back("the materials call for " + effect_names(ignored) + ", which model " + entry.name +
                              " does not implement: ignored");
  }

  // Rolling resistance is compiled with sliding friction only (LAMMPS's granular styles always
  // have a tangential model too); derived sets add it above.
  if ((s.model.effects & kRolling) && !(s.model.effects & kFriction))
    throw SceneError(
        "model.effects: rolling without friction: rolling resistance is compiled with the friction "
        "effect; add \"friction\" to [model] effects (with friction = 0 it adds no tangential force)");

  // The model's own check (options against materials and effects) and its adhesive range: the
  // largest separation at which a contact stays active. The skin must exceed it, or an adhesive
  // contact at negative overlap would drop out of the list at the next rebuild.
  double range = 0.0;
  if (entry.scene_check) {
    try {
      range = entry.scene_check(s);
    } catch (const SceneError&) { throw; } catch (const ParameterError& e) {
      throw SceneError(std::string("[model] ") + e.what());
    }
  }
  const double default_skin = 0.2 * s.min_radius();
  if (s.run.skin < 0) {
    s.run.skin = std::max(default_skin, 1.25 * range);
    if (s.run.skin > default_skin)
      s.model.notes.push_back("skin raised to 1.25 x the adhesive range of model " + entry.name + " (" +
                              std::to_string(range) + " m)");
  } else if (range > 0.0 && !(s.run.skin > range)) {
    std::ostringstream m;
    m << "run.skin = " << s.run.skin << " is not larger than the adhesive range " << range << " m of model "
      << entry.name << " (the largest separation at which an adhesive contact stays active): such contacts "
      << "would drop out of the contact list; give run.skin > " << range << " or leave it out (default "
      << "max(0.2 x the smallest radius, 1.25 x the adhesive range))";
    throw SceneError(m.str());
  }
  check_periodic_lengths(s);
}

Scene parse_table(const toml::table& root, const std::string& source) {
  Scene s;
  s.source = source;
  TableReader top(root, "");
  s.description = top.string("description").value_or("");
  parse_materials(top, s);  // first: the others refer to materials by name
  parse_model(top, s);
  parse_box(top, s);  // before the particles: the lattice origin defaults to box.lo
  parse_particles(top, s);
  parse_walls(top, s);
  s.gravity = top.vec3("gravity", Vec3d{0, 0, 0}, &kGravity);
  parse_run(top, s);
  top.finish();
  finish_scene(s);
  return s;
}

[[noreturn]] void rethrow_syntax(const toml::parse_error& e, const std::string& source) {
  std::ostringstream m;
  m << source << ":" << e.source().begin.line << ":" << e.source().begin.column
    << ": TOML syntax error: " << e.description();
  throw SceneError(m.str());
}

}  // namespace

Vec3d WallSpec::displacement(double t0, double t1) const {
  if (segments.empty()) {
    Vec3d d{0, 0, 0};
    for (int k = 0; k < 3; ++k) d[k] = velocity[k] * (t1 - t0);
    return d;
  }
  return segments_displacement(segments, t0, t1);
}

Vec3d segments_displacement(const std::vector<MotionSegment>& segments, double t0, double t1) {
  Vec3d d{0, 0, 0};
  double start = 0.0;
  for (const auto& seg : segments) {
    const double end = start + seg.duration;
    const double overlap = std::min(t1, end) - std::max(t0, start);
    if (overlap > 0)
      for (int k = 0; k < 3; ++k) d[k] += seg.velocity[k] * overlap;
    start = end;
    if (start >= t1) break;
  }
  return d;
}

double Scene::min_radius() const {
  double r = kInf;
  for (const auto& p : particles) r = std::min(r, p.radius);
  return r;
}
double Scene::max_radius() const {
  double r = 0;
  for (const auto& p : particles) r = std::max(r, p.radius);
  return r;
}
double rayleigh_time(const Scene& s) {
  double t = kInf;
  for (const auto& p : s.particles) {
    const Material& m = s.materials[p.material];
    if (m.rigid) continue;
    const double tr = M_PI * p.radius * std::sqrt(m.density / m.shear_modulus()) / (0.1631 * m.poisson_ratio + 0.8766);
    t = std::min(t, tr);
  }
  return t;
}

bool Scene::any_driven() const {
  return std::any_of(particles.begin(), particles.end(), [](const ParticleSpec& p) { return p.driven; });
}

Scene parse_scene_file(const std::string& path) {
  try {
    return parse_table(toml::parse_file(path), path);
  } catch (const toml::parse_error& e) { rethrow_syntax(e, path); }
}

Scene parse_scene_string(const std::string& text, const std::string& source) {
  try {
    return parse_table(toml::parse(text, source), source);
  } catch (const toml::parse_error& e) { rethrow_syntax(e, source); }
}

}  // namespace driver
}  // namespace epac
