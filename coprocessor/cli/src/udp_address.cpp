#include "udp_address.hpp"

#include <algorithm>

#include "scene_options.hpp"

namespace safecell {

UdpEndpoint udp_address(const std::string& option, const std::string& text, int port_from) {
  const std::size_t colon = text.rfind(':');
  const std::string expected =
      "HOST:PORT with a port of " + std::to_string(port_from) + "..65535, e.g. 192.168.10.2:47701";
  if (colon == std::string::npos || colon == 0 || colon + 1 == text.size()) {
    bad_option(option, text, expected);
  }
  const std::string port_text = text.substr(colon + 1);
  if (port_text.size() > 5 || !std::all_of(port_text.begin(), port_text.end(),
                                           [](char c) { return c >= '0' && c <= '9'; })) {
    bad_option(option, text, expected);
  }
  const int port = std::stoi(port_text);
  if (port < port_from || port > 65535) bad_option(option, text, expected);
  return {text.substr(0, colon), static_cast<unsigned short>(port)};
}

}  // namespace safecell
