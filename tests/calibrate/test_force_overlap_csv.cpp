// The CSV reader of epac-calibrate (drivers/calibrate/force_overlap_csv.hpp): layouts, header,
// comments, ragged columns, errors naming the line, and an exact round trip at 17 digits.
#include "calibrate/force_overlap_csv.hpp"

#include <catch2/catch.hpp>
#include <epac/params/validation.hpp>

#include <sstream>

using namespace epac;
using namespace epac::calibrate;

TEST_CASE("force-overlap CSV: layouts, header, comments, ragged columns and errors", "[calibrate][csv]") {
  std::istringstream a("overlap force\n0 1\n1e-9 2.5\n");
  auto c = parse_force_overlap_csv(a);
  REQUIRE(c.size() == 1);
  CHECK(c[0].overlap.size() == 2);
  CHECK(c[0].force[1] == 2.5);
  std::istringstream b("# two curves\n1,2,3,4\n5,6,,\n");
  c = parse_force_overlap_csv(b);
  REQUIRE(c.size() == 2);
  CHECK(c[0].overlap.size() == 2);
  CHECK(c[1].overlap.size() == 1);
  std::istringstream bad1("1,2,3\n");
  CHECK_THROWS_WITH(parse_force_overlap_csv(bad1), Catch::Contains("even number"));
  std::istringstream bad2("1,2\n3,x\n");
  CHECK_THROWS_WITH(parse_force_overlap_csv(bad2), Catch::Contains(":2"));
  std::istringstream bad3("1,2,3,\n");
  CHECK_THROWS_AS(parse_force_overlap_csv(bad3), ParameterError);
  CHECK_THROWS_AS(read_force_overlap_csv("/nonexistent/file.csv"), ParameterError);
}

TEST_CASE("force-overlap CSV: three curves written at 17 digits read back bit for bit", "[calibrate][csv]") {
  std::ostringstream csv;
  csv.precision(17);
  csv << "# synthetic\noverlap_1,force_1,overlap_2,force_2,overlap_3,force_3\n";
  for (int k = 0; k < 50; ++k)
    for (int i = 0; i < 3; ++i)
      csv << (i ? "," : "") << 1e-9 * k / 3.0 * (i + 1) << "," << 1e-6 / (k + 7.0) << (i == 2 ? "\n" : "");
  std::istringstream is(csv.str());
  const auto parsed = parse_force_overlap_csv(is);
  REQUIRE(parsed.size() == 3);
  for (int i = 0; i < 3; ++i) {
    REQUIRE(parsed[i].overlap.size() == 50);
    for (int k = 0; k < 50; ++k) {
      CHECK(parsed[i].overlap[k] == 1e-9 * k / 3.0 * (i + 1));
      CHECK(parsed[i].force[k] == 1e-6 / (k + 7.0));
    }
  }
}
