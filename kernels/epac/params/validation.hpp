#pragma once
// Host-side parameter checks. Every check throws before any kernel runs, with a message that
// names the parameter, its value and the valid range.
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace epac {

class ParameterError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

enum class Bound { open, closed };

// Requires lo (<|<=) value (<|<=) hi and finite unless allow_inf. Throws ParameterError.
inline void require_range(const std::string& name, double value, double lo, Bound lo_kind, double hi,  // host
                          Bound hi_kind, bool allow_inf = false) {
  const bool is_nan = std::isnan(value);
  const bool inf_ok = allow_inf && std::isinf(value) && value > 0;
  bool ok = !is_nan && (std::isfinite(value) || inf_ok);
  if (ok && !inf_ok) {
    ok = (lo_kind == Bound::open ? value > lo : value >= lo) && (hi_kind == Bound::open ? value < hi : value <= hi);
  }
  if (!ok) {
    std::ostringstream s;
    s << name << " = " << value << " is outside the valid range " << (lo_kind == Bound::open ? "(" : "[") << lo << ", ";
    if (std::isinf(hi))
      s << "inf" << (allow_inf ? "]" : ")");
    else
      s << hi << (hi_kind == Bound::open ? ")" : "]");
    throw ParameterError(s.str());  // host
  }
}

inline void require_positive(const std::string& name, double value, bool allow_inf = false) {  // host
  require_range(name, value, 0.0, Bound::open, std::numeric_limits<double>::infinity(), Bound::open, allow_inf);
}

// Requires a constant derived on the host (in double) to be usable in the kernels' scalar type T:
// finite, and 0 or of magnitude within T's normal range [numeric_limits<T>::min(), max()]. In float a
// modulus, energy or yield stress whose derived constant overflows becomes inf, and one that
// underflows becomes 0 or a denormal that a later division turns into inf; create rejects such
// inputs instead of running to Inf/NaN (docs/stability.md).
// `from` names the inputs the constant is derived from.
template <class T>
void require_representable(const std::string& name, double value, const std::string& from) {  // host
  const double lo = static_cast<double>(std::numeric_limits<T>::min());
  const double hi = static_cast<double>(std::numeric_limits<T>::max());
  const double a = std::fabs(value);
  if (std::isfinite(value) && (a == 0.0 || (a >= lo && a <= hi))) return;
  std::ostringstream s;
  s << name << " = " << value << " (derived from " << from << ") is outside the range representable in "
    << (sizeof(T) == sizeof(float)    ? "float"
        : sizeof(T) == sizeof(double) ? "double"
                                      : "the scalar type")
    << ": |value| must be 0 or in [" << lo << ", " << hi << "]";
  throw ParameterError(s.str());  // host
}

}  // namespace epac
