// safecell-faultproxy: the fault-injecting UDP proxy as a program, for fault campaigns by hand or
// by script between a coprocessor and a controller on one machine. Side A (the coprocessor) sends
// to --listen-a, side B (the controller) to --listen-b; the proxy forwards between them with the
// faults asked for, then prints what it did as JSON.
//
//   safecell-faultproxy --listen-a 47001 --listen-b 47002 --peer-b 47010 --drop 0.05 --seconds 60

#include <CLI/CLI.hpp>
#include <chrono>
#include <csignal>
#include <iostream>
#include <thread>

#include "safecell/faultproxy/fault_proxy.hpp"

namespace {

volatile std::sig_atomic_t g_stop = 0;
extern "C" void on_signal(int /*signal*/) { g_stop = 1; }

}  // namespace

int main(int argc, char** argv) {
  using safecell::FaultRates;
  CLI::App app{
      "safecell-faultproxy: a UDP proxy that drops, duplicates, reorders, delays, "
      "corrupts (below or above the CRC), inserts and cuts, seeded; prints what it did as JSON"};
  safecell::FaultProxySettings settings;
  FaultRates rates;
  std::string direction = "both";
  double seconds = 0.0;
  int delay_ms = 60;
  int cut_after_ms = 0;
  int cut_ms = 0;
  app.add_option("--ip", settings.ip, "Address to bind and forward on")->capture_default_str();
  app.add_option("--listen-a", settings.listen_a, "Port side A (the coprocessor) sends to");
  app.add_option("--listen-b", settings.listen_b, "Port side B (the controller) sends to");
  app.add_option("--peer-a", settings.peer_a, "Side A's port (0: learnt from its first datagram)");
  app.add_option("--peer-b", settings.peer_b, "Side B's port (0: learnt from its first datagram)");
  const auto probability = CLI::Range(0.0, 1.0);
  app.add_option("--drop", rates.drop, "Probability a datagram is dropped")->check(probability);
  app.add_option("--duplicate", rates.duplicate, "... sent twice")->check(probability);
  app.add_option("--reorder", rates.reorder, "... held back behind the next")->check(probability);
  app.add_option("--delay", rates.delay, "... held back by --delay-ms")->check(probability);
  app.add_option("--delay-ms", delay_ms, "How long a delayed datagram is held")
      ->check(CLI::Range(0, 10'000))
      ->capture_default_str();
  app.add_option("--flip", rates.flip, "... has bits flipped")->check(probability);
  app.add_option("--max-flipped-bits", rates.max_flipped_bits, "Bits flipped at most")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  app.add_option("--insert", rates.insert, "... is preceded by a foreign frame")
      ->check(probability);
  app.add_option("--foreign-session", rates.foreign_session,
                 "... is preceded by a copy under another session (needs --fingerprint)")
      ->check(probability);
  app.add_option("--resealed-flip", rates.resealed_flip,
                 "... has payload bits flipped and is sealed again (needs --fingerprint)")
      ->check(probability);
  app.add_option("--fingerprint", settings.configuration_fingerprint,
                 "The session's CRC fingerprint, for --foreign-session");
  app.add_option("--cut-after-ms", cut_after_ms, "The link is cut this long after the start")
      ->check(CLI::Range(0, 86'400'000));
  app.add_option("--cut-ms", cut_ms, "... for this long (0: no cut)")
      ->check(CLI::Range(0, 86'400'000));
  app.add_option("--direction", direction, "Where the faults apply")
      ->check(CLI::IsMember({"both", "a-to-b", "b-to-a"}))
      ->capture_default_str();
  app.add_option("--seed", settings.seed, "Seed of the faults")->capture_default_str();
  app.add_option("--seconds", seconds, "Stop after this long (0: at Ctrl-C)")
      ->check(CLI::Range(0.0, 86'400.0));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? 0 : 2;
  }
  rates.delay_by = std::chrono::milliseconds(delay_ms);
  rates.cut_after = std::chrono::milliseconds(cut_after_ms);
  rates.cut_for = std::chrono::milliseconds(cut_ms);
  if (direction != "b-to-a") settings.a_to_b = rates;
  if (direction != "a-to-b") settings.b_to_a = rates;
  try {
    safecell::FaultProxy proxy(settings);
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    proxy.start();
    std::cerr << "safecell-faultproxy: side A sends to " << settings.ip << ':' << proxy.port_a()
              << ", side B to " << settings.ip << ':' << proxy.port_b() << '\n';
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (g_stop == 0 && (seconds == 0.0 || std::chrono::steady_clock::now() < until)) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    proxy.stop();
    std::cout << proxy.report_json() << '\n';
  } catch (const std::exception& error) {
    std::cerr << "safecell-faultproxy: " << error.what() << '\n';
    return 2;
  }
  return 0;
}
