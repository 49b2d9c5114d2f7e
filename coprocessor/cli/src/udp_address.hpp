#pragma once
// "HOST:PORT" options of the link's commands. Private to the CLI.

#include <string>

#include "safecell/link/udp_transport.hpp"

namespace safecell {

// `text` as an address and a port of port_from..65535 (port_from 0: a local address that may take
// any free port). Throws std::invalid_argument naming the option, the value and what was expected.
UdpEndpoint udp_address(const std::string& option, const std::string& text, int port_from);

}  // namespace safecell
