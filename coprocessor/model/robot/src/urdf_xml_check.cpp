#include "urdf_xml_check.hpp"

#include <tinyxml2.h>

#include <algorithm>
#include <array>
#include <initializer_list>
#include <string_view>

#include "safecell/robot/robot_error.hpp"

namespace safecell {
namespace {

using Names = std::initializer_list<std::string_view>;

// An element of a link or joint that the loader reads: the attributes and child elements it may
// have. Elements the loader does not read (inertial, material, dynamics, ...) are allowed where
// the format puts them and not looked into.
struct ElementRule {
  std::string_view name;
  Names attributes;
  Names children;
};

constexpr std::array<std::string_view, 6> kNotRead = {
    "inertial", "material", "dynamics", "mimic", "safety_controller", "calibration"};

const std::array<ElementRule, 14>& rules() {
  static const std::array<ElementRule, 14> table{{
      {"link", {"name", "type"}, {"inertial", "visual", "collision"}},
      {"collision", {"name"}, {"origin", "geometry"}},
      {"visual", {"name"}, {"origin", "geometry", "material"}},
      {"origin", {"xyz", "rpy"}, {}},
      {"geometry", {}, {"box", "cylinder", "sphere", "mesh"}},
      {"box", {"size"}, {}},
      {"cylinder", {"radius", "length"}, {}},
      {"sphere", {"radius"}, {}},
      {"mesh", {"filename", "scale"}, {}},
      {"joint",
       {"name", "type"},
       {"parent", "child", "origin", "axis", "limit", "dynamics", "mimic", "safety_controller",
        "calibration"}},
      {"parent", {"link"}, {}},
      {"child", {"link"}, {}},
      {"axis", {"xyz"}, {}},
      {"limit", {"lower", "upper", "effort", "velocity"}, {}},
  }};
  return table;
}

// Every element a rule lets in, but those not read, has a rule of its own.
const ElementRule& rule_of(std::string_view name) {
  const auto& table = rules();
  return *std::find_if(table.begin(), table.end(),
                       [&](const ElementRule& rule) { return rule.name == name; });
}

bool contains(Names names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string listed(Names names) {
  std::string text;
  std::size_t k = 0;
  for (const std::string_view name : names) {
    text += k == 0 ? "" : (k + 1 == names.size() ? " or " : ", ");
    text += name;
    ++k;
  }
  return text;
}

class UrdfXmlCheck {
 public:
  explicit UrdfXmlCheck(const std::string& source) : source_(source) {}

  void check_top(const tinyxml2::XMLElement& robot) const {
    for (const tinyxml2::XMLElement* child = robot.FirstChildElement(); child != nullptr;
         child = child->NextSiblingElement()) {
      const std::string_view name = child->Name();
      if (name != "link" && name != "joint") continue;  // materials, transmissions, gazebo tags
      const char* owner_name = child->Attribute("name");
      const std::string owner =
          std::string(name) + " '" + (owner_name != nullptr ? owner_name : "") + "'";
      check_element(*child, rule_of(name), owner);
    }
  }

 private:
  [[noreturn]] void fail(const tinyxml2::XMLElement& at, const std::string& owner,
                         const std::string& problem) const {
    throw RobotError(source_ + ":" + std::to_string(at.GetLineNum()) + ": " + owner + ": " +
                     problem);
  }

  void check_element(const tinyxml2::XMLElement& element, const ElementRule& rule,
                     const std::string& owner) const {
    for (const tinyxml2::XMLAttribute* attribute = element.FirstAttribute(); attribute != nullptr;
         attribute = attribute->Next()) {
      if (!contains(rule.attributes, attribute->Name())) {
        fail(element, owner,
             "<" + std::string(rule.name) + "> has an attribute '" + attribute->Name() +
                 "', expected " +
                 (rule.attributes.size() == 0 ? std::string("none")
                                              : "only " + listed(rule.attributes)));
      }
    }
    int geometry_kinds = 0;
    for (const tinyxml2::XMLElement* child = element.FirstChildElement(); child != nullptr;
         child = child->NextSiblingElement()) {
      const std::string_view name = child->Name();
      if (!contains(rule.children, name)) {
        fail(*child, owner,
             "<" + std::string(rule.name) + "> holds an element <" + std::string(name) +
                 ">, expected " +
                 (rule.children.size() == 0 ? std::string("none") : listed(rule.children)));
      }
      if (rule.name == "geometry") ++geometry_kinds;
      if (std::find(kNotRead.begin(), kNotRead.end(), name) != kNotRead.end()) continue;
      check_element(*child, rule_of(name), owner);
    }
    if (rule.name == "geometry" && geometry_kinds != 1) {
      fail(element, owner,
           "<geometry> holds " + std::to_string(geometry_kinds) +
               " shapes, expected exactly one of " + listed(rule.children));
    }
  }

  const std::string& source_;
};

}  // namespace

void check_urdf_xml(const std::string& xml, const std::string& source) {
  if (xml.size() > kMaxUrdfBytes) {
    throw RobotError(source + ": " + std::to_string(xml.size()) + " bytes, expected at most " +
                     std::to_string(kMaxUrdfBytes) + " for a robot description");
  }
  tinyxml2::XMLDocument document;
  if (document.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS) {
    const std::string problem = document.ErrorID() == tinyxml2::XML_ELEMENT_DEPTH_EXCEEDED
                                    ? "elements nested deeper than " +
                                          std::to_string(TINYXML2_MAX_ELEMENT_DEPTH) +
                                          ", expected a robot description"
                                    : std::string("not well-formed XML: ") + document.ErrorStr();
    throw RobotError(source + ":" + std::to_string(document.ErrorLineNum()) + ": " + problem);
  }
  const tinyxml2::XMLElement* robot = document.RootElement();
  if (robot == nullptr || std::string_view(robot->Name()) != "robot") {
    throw RobotError(source + ": not a valid URDF: the top element is not <robot>");
  }
  UrdfXmlCheck(source).check_top(*robot);
}

}  // namespace safecell
