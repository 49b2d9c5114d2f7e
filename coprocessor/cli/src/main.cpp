#include <iostream>

#include "safecell/cli/cli_app.hpp"

int main(int argc, char** argv) { return safecell::run_safecell(argc, argv, std::cout, std::cerr); }
