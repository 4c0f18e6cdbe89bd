// History remap across list rebuilds: persisting contacts keep their rows (whatever their new
// index and i/j order), new contacts start from zero, vanished ones are dropped.
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/compute/history_remap.hpp>

using namespace epac;

namespace {
template <class D>
ContactList<D> make_list(const std::vector<std::pair<int, int>>& pairs) {
  ContactList<D> c(static_cast<int>(pairs.size()));
  auto f = Kokkos::create_mirror_view(c.first);
  auto s = Kokkos::create_mirror_view(c.second);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    f(k) = pairs[k].first;
    s(k) = pairs[k].second;
  }
  Kokkos::deep_copy(c.first, f);
  Kokkos::deep_copy(c.second, s);
  return c;
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("history follows its contact through a rebuild", "[remap]", test::Backends) {
  using D = TestType;
  using T = double;
  Particles<T, D> p(6);
  {
    auto g = Kokkos::create_mirror_view(p.gid);
    const std::int64_t gids[6] = {40, 7, 1000003, 12, 5, 99};  // global ids unrelated to indices
    for (int i = 0; i < 6; ++i) g(i) = gids[i];
    Kokkos::deep_copy(p.gid, g);
  }
  const int fields = 4;
  auto old_list = make_list<D>({{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}});
  ContactHistory<T, D> old(pair_contact_keys(p, old_list), fields);
  {
    auto d = Kokkos::create_mirror_view(old.data);
    for (int k = 0; k < old_list.count; ++k)
      for (int f = 0; f < fields; ++f) d(k, f) = 100.0 * (k + 1) + f;
    Kokkos::deep_copy(old.data, d);
  }
  // new list: (2,1) is old contact 1 with i/j swapped, (4,3) old 3, (0,5) and (1,4) are new,
  // (0,1), (2,3), (4,5) vanished.
  auto new_list = make_list<D>({{0, 5}, {2, 1}, {1, 4}, {4, 3}});
  auto fresh = remap_history(old, pair_contact_keys(p, new_list), fields);
  auto d = test::to_host(fresh.data);
  REQUIRE(fresh.data.extent(0) == 4);
  for (int f = 0; f < fields; ++f) {
    CHECK(d(0, f) == 0.0);
    CHECK(d(1, f) == 200.0 + f);
    CHECK(d(2, f) == 0.0);
    CHECK(d(3, f) == 400.0 + f);
  }
  // Wall keys are (gid, wall): the same particle on another wall is a new contact.
  auto wl_old = make_list<D>({{2, 0}, {3, 1}});
  ContactHistory<T, D> wold(wall_contact_keys(p, wl_old), 1);
  Kokkos::deep_copy(wold.data, 5.0);
  auto wl_new = make_list<D>({{2, 1}, {3, 1}});
  auto wfresh = remap_history(wold, wall_contact_keys(p, wl_new), 1);
  auto wd = test::to_host(wfresh.data);
  CHECK(wd(0, 0) == 0.0);
  CHECK(wd(1, 0) == 5.0);
}

TEMPLATE_LIST_TEST_CASE("remap of a large shuffled list keeps every row", "[remap]", test::Backends) {
  using D = TestType;
  using T = float;
  const int n = 3000;
  Particles<T, D> p(n);
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, n),
      KOKKOS_LAMBDA(int i) { p.gid(i) = 3 * static_cast<std::int64_t>(i) + 1; });
  std::vector<std::pair<int, int>> a, b;
  for (int i = 0; i + 1 < n; ++i) a.push_back({i, i + 1});
  for (int i = n - 2; i >= 0; i -= 2) b.push_back({i + 1, i});  // every other contact, reversed
  auto la = make_list<D>(a), lb = make_list<D>(b);
  ContactHistory<T, D> old(pair_contact_keys(p, la), 1);
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, la.count), KOKKOS_LAMBDA(int k) { old.data(k, 0) = T(k); });
  auto fresh = remap_history(old, pair_contact_keys(p, lb), 1);
  auto d = test::to_host(fresh.data);
  int wrong = 0;
  for (int k = 0; k < lb.count; ++k) wrong += d(k, 0) != T(b[k].second);  // old index of (i, i+1) is i
  CHECK(wrong == 0);
}

// docs/install.md's host program: a history built from the contact list's keys keeps its rows through a
// remap with the identical list (the keyless form used to come back all zero, silently).
TEMPLATE_LIST_TEST_CASE("a keyed history survives a remap with the same list, a keyless one is refused", "[remap]",
                        test::Backends) {
  using D = TestType;
  using T = double;
  Particles<T, D> p(3);
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, 3), KOKKOS_LAMBDA(int i) { p.gid(i) = 10 + i; });
  auto list = make_list<D>({{0, 1}, {1, 2}});
  ContactHistory<T, D> keyed(pair_contact_keys(p, list), 3);
  REQUIRE(keyed.has_keys());
  Kokkos::deep_copy(keyed.data, 7.0);
  auto same = remap_history(keyed, pair_contact_keys(p, list), 3);
  auto d = test::to_host(same.data);
  for (int k = 0; k < 2; ++k)
    for (int f = 0; f < 3; ++f) CHECK(d(k, f) == 7.0);

  ContactHistory<T, D> keyless(list.count, 3);
  CHECK_FALSE(keyless.has_keys());
  CHECK_THROWS_AS(remap_history(keyless, pair_contact_keys(p, list), 3), ParameterError);
  CHECK_THROWS_WITH(remap_history(keyless, pair_contact_keys(p, list), 3), Catch::Contains("no keys"));
  // Rows of another model's width are refused too, not zeroed.
  CHECK_THROWS_WITH(remap_history(keyed, pair_contact_keys(p, list), 4), Catch::Contains("fields = 4"));
  // An empty keyless history (the first build) is fine: every contact is new.
  ContactHistory<T, D> empty;
  CHECK(remap_history(empty, pair_contact_keys(p, list), 3).rows() == 2);
}
