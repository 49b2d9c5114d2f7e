#include "safecell/cli/text_table.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>

namespace safecell {
namespace {

TEST(TextTable, AlignsColumns) {
  TextTable table({{"name", TextTable::Align::kLeft}, {"cells", TextTable::Align::kRight}});
  table.add_row({"j1", "45"});
  table.add_row({"shoulder", "5"});
  std::ostringstream out;
  table.print(out);
  EXPECT_EQ(out.str(),
            "name      cells\n"
            "j1           45\n"
            "shoulder      5\n");
  EXPECT_THROW(table.add_row({"only one"}), std::invalid_argument);
}

TEST(TextTable, NumberFormatting) {
  EXPECT_EQ(fixed(7.1234, 2), "7.12");
  EXPECT_EQ(grouped(165375), "165,375");
  EXPECT_EQ(grouped(999), "999");
  EXPECT_EQ(grouped(1000000), "1,000,000");
}

}  // namespace
}  // namespace safecell
