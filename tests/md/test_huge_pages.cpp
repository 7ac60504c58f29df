// HugePageAllocator (md/huge_pages.hpp): large blocks are 2 MiB aligned (so that huge pages can
// back them), small ones keep their type's alignment, and both hold their contents through growth.
#include <catch2/catch.hpp>
#include <cstdint>

#include "md/huge_pages.hpp"
#include "md/particles.hpp"

using namespace coldblast::md;

TEST_CASE("huge-page vectors: large blocks 2 MiB aligned, small ones ordinary, contents kept", "[fast]") {
  HugeVector<double> small(1000, 1.5);
  REQUIRE(reinterpret_cast<std::uintptr_t>(small.data()) % alignof(double) == 0);
  HugeVector<std::int64_t> grown;
  for (std::int64_t k = 0; k < 600000; ++k) grown.push_back(k * k);  // crosses 2 MiB while growing
  REQUIRE(grown.capacity() * sizeof(std::int64_t) >= huge_page_bytes);
  REQUIRE(reinterpret_cast<std::uintptr_t>(grown.data()) % huge_page_bytes == 0);
  std::int64_t mismatches = 0;
  for (std::int64_t k = 0; k < 600000; ++k) mismatches += grown[static_cast<std::size_t>(k)] != k * k;
  REQUIRE(mismatches == 0);
  HugeVector<Particle<3>> particles(40000);  // 2.56 MB of 64-byte particles
  REQUIRE(reinterpret_cast<std::uintptr_t>(particles.data()) % huge_page_bytes == 0);
  HugeVector<Particle<3>> few(10);
  REQUIRE(reinterpret_cast<std::uintptr_t>(few.data()) % 64 == 0);  // the 3D particle's own alignment
}
