// Cell list (md/cell_list.*): the tabulated periodic stencils against a brute force over cell
// coordinates (every cell of small boxes, 2D and 3D, 3 to 5 cells per axis), in order, with their
// image shifts; insert and remove keep every cell's list exact, next(-1) = -1.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <random>
#include <set>
#include <vector>

#include "md/cell_list.hpp"

using namespace coldblast::md;

namespace {
// The neighbours of `cell` at offsets o (o[axis] = direction only, when axis >= 0), axis 0
// fastest, each as (index, shift) from coordinates wrapped by hand.
template <int D>
std::vector<std::pair<std::int32_t, Vec<D>>> brute_force(const CellList<D>& cells, std::int32_t cell, int axis,
                                                         int direction) {
  std::vector<std::pair<std::int32_t, Vec<D>>> out;
  const auto c = cells.coordinates(cell);
  std::array<int, D> o;
  const int total = D == 2 ? 9 : 27;
  for (int m = 0; m < total; ++m) {
    int rest = m;
    bool keep = true;
    for (int k = 0; k < D; ++k, rest /= 3) {
      o[k] = rest % 3 - 1;
      if (k == axis && o[k] != direction) keep = false;
    }
    if (!keep) continue;
    std::array<std::int32_t, D> n;
    Vec<D> shift = Vec<D>::Zero();
    for (int k = 0; k < D; ++k) {
      n[k] = c[k] + o[k];
      if (n[k] < 0) {
        n[k] += cells.count(k);
        shift[k] = -cells.box()[k];
      } else if (n[k] >= cells.count(k)) {
        n[k] -= cells.count(k);
        shift[k] = cells.box()[k];
      }
    }
    out.emplace_back(cells.index(n), shift);
  }
  return out;
}

template <int D>
void check_stencils(const Vec<D>& box) {
  const CellList<D> cells = CellList<D>::periodic(box, 1.0, 10);
  int wrapping = 0;
  for (std::int32_t cell = 0; cell < cells.cell_count(); ++cell) {
    std::vector<std::pair<std::int32_t, Vec<D>>> got;
    cells.for_each_neighbour_cell(cell, [&](std::int32_t n, const Vec<D>& s) { got.emplace_back(n, s); });
    REQUIRE(got == brute_force<D>(cells, cell, -1, 0));
    wrapping += cells.wraps(cell);
    for (int axis = 0; axis < D; ++axis)
      for (const int direction : {-1, 1}) {
        got.clear();
        cells.for_each_new_neighbour_cell(cell, axis, direction,
                                          [&](std::int32_t n, const Vec<D>& s) { got.emplace_back(n, s); });
        REQUIRE(got == brute_force<D>(cells, cell, axis, direction));
      }
  }
  REQUIRE(wrapping > 0);
}
}  // namespace

TEST_CASE("periodic cell stencils (tabulated per face class) match a brute force over coordinates", "[fast]") {
  check_stencils<2>(Vec<2>(3.5, 5.2));
  check_stencils<2>(Vec<2>(4.0, 3.0));
  check_stencils<3>(Vec<3>(3.2, 4.1, 5.9));
  check_stencils<3>(Vec<3>(3.0, 3.0, 3.0));
}

TEST_CASE("cell lists stay exact through random inserts and removals; next(-1) = -1", "[fast]") {
  CellList<3> cells = CellList<3>::periodic(Vec<3>(4.0, 4.0, 4.0), 1.0, 200);
  REQUIRE(cells.next(-1) == -1);
  std::mt19937_64 rng(7);
  std::vector<std::int32_t> where(200, -1);
  for (int step = 0; step < 20000; ++step) {
    const auto id = static_cast<std::int32_t>(rng() % 200);
    if (where[id] >= 0) cells.remove(id, where[id]);
    where[id] = static_cast<std::int32_t>(rng() % static_cast<std::uint64_t>(cells.cell_count()));
    cells.insert(id, where[id]);
  }
  REQUIRE(cells.next(-1) == -1);
  for (std::int32_t cell = 0; cell < cells.cell_count(); ++cell) {
    std::multiset<std::int32_t> listed, expected;
    for (std::int32_t id = cells.first(cell); id >= 0; id = cells.next(id)) listed.insert(id);
    for (std::int32_t id = 0; id < 200; ++id)
      if (where[id] == cell) expected.insert(id);
    REQUIRE(listed == expected);
    const std::int32_t* links = cells.links();
    std::multiset<std::int32_t> raw;
    for (std::int32_t id = cells.heads()[cell]; id >= 0; id = links[id]) raw.insert(id);
    REQUIRE(raw == expected);
  }
}
