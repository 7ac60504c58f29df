// Binary state files (common/bytes.hpp): values, arrays and texts round-trip bit for bit, and a
// reader given too few bytes, or a length beyond the file, refuses with the source and the offset.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "common/bytes.hpp"

using coldblast::common::ByteReader;
using coldblast::common::ByteWriter;
using coldblast::common::fnv1a64;

TEST_CASE("a byte writer's values, arrays and texts read back bit for bit", "[fast]") {
  ByteWriter out;
  const double tiny = std::numeric_limits<double>::denorm_min(), nan = std::numeric_limits<double>::quiet_NaN();
  out.put(-0.0);
  out.put(tiny);
  out.put(nan);
  out.put<std::int32_t>(-7);
  out.put<std::uint64_t>(18446744073709551615ULL);
  const std::vector<double> values{1.0, 0.1, -3e300};
  out.put_vector(values);
  out.put_vector(std::vector<std::uint8_t>{});
  out.put_string(std::string("a\0b", 3));
  const std::string bytes = out.take();
  CHECK(bytes.size() == 8 + 8 + 8 + 4 + 8 + (8 + 24) + 8 + (8 + 3));

  ByteReader in(bytes, "test");
  const double zero = in.get<double>();
  CHECK(std::signbit(zero));
  CHECK(in.get<double>() == tiny);
  CHECK(std::isnan(in.get<double>()));
  CHECK(in.get<std::int32_t>() == -7);
  CHECK(in.get<std::uint64_t>() == 18446744073709551615ULL);
  CHECK(in.get_vector<double>() == values);
  CHECK(in.get_vector<std::uint8_t>().empty());
  CHECK(in.get_string() == std::string("a\0b", 3));
  CHECK(in.remaining() == 0);
}

TEST_CASE("a byte reader refuses to read past the end, naming the source and the offset", "[fast]") {
  ByteWriter out;
  out.put<std::uint64_t>(1000);  // an array of 1000 doubles announced, 2 given
  out.put(1.0);
  out.put(2.0);
  const std::string bytes = out.take();
  {
    ByteReader in(bytes, "state.bin");
    CHECK_THROWS_WITH(in.get_vector<double>(), Catch::Contains("state.bin") &&
                                                   Catch::Contains("longer than the file") &&
                                                   Catch::Contains("at byte 8"));
  }
  {
    ByteReader in(bytes, "state.bin");
    CHECK_THROWS_WITH(in.get_string(), Catch::Contains("longer than the file"));
  }
  {
    const std::string cut = bytes.substr(0, 5);
    ByteReader in(cut, "cut");
    CHECK_THROWS_WITH(in.get<std::uint64_t>(), Catch::Contains("cut: truncated (8 bytes wanted) at byte 0"));
  }
}

TEST_CASE("fnv1a64 is FNV-1a: the published test values", "[fast]") {
  // From the FNV reference (Fowler, Noll, Vo; draft-eastlake-fnv): "" and "a" and "foobar".
  CHECK(fnv1a64("", 0) == 0xcbf29ce484222325ULL);
  CHECK(fnv1a64("a", 1) == 0xaf63dc4c8601ec8cULL);
  CHECK(fnv1a64("foobar", 6) == 0x85944171f73967e8ULL);
}
