#pragma once
// The URDF's XML checked before urdfdom sees it. urdfdom parses with TinyXML 1, which recurses once
// per nesting level (a file nested 100,000 deep overflows the stack), and it passes over elements
// and attributes it does not know: a misspelt <colision> or <orgin>, or xzy= for xyz=, would
// silently take a link's geometry or a joint's offset out of the model. tinyxml2 reads the text
// first (it refuses nesting deeper than its limit of 100 instead of recursing on), then every
// element and attribute of links and joints must be one urdfdom reads or one the format allows.
// Private to the robot module.

#include <cstddef>
#include <string>

namespace safecell {

// Larger is no robot description: the biggest URDFs with all their links are a few hundred kB.
inline constexpr std::size_t kMaxUrdfBytes = std::size_t{16} << 20;

// Throws RobotError "<source>: ..." naming the line, the link or joint, the element and what was
// expected.
void check_urdf_xml(const std::string& xml, const std::string& source);

}  // namespace safecell
