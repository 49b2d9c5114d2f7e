#include "demo_maps.hpp"

#include "model_fixture.hpp"
#include "safecell/validation/demo_maps.hpp"

namespace safecell::test {

const DemoMaps& demo_maps() {
  static const DemoMaps maps = [] {
    const CoarseTables tables;
    // 2 s of the demo from just before the person walks in.
    return DemoMaps{tables.grid, demo_map_sequence(tables.cell, tables.grid, tables.luts,
                                                   tables.silhouettes, 0.5, 60)};
  }();
  return maps;
}

}  // namespace safecell::test
