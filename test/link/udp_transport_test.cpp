// The coprocessor's UDP transport on loopback: a receive with no time to wait takes what is
// already waiting and returns at once when nothing is; datagrams from anyone but the peer are
// dropped.

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdint>

#include "safecell/link/udp_transport.hpp"

namespace safecell {
namespace {

using namespace std::chrono_literals;

TEST(UdpTransport, AReceiveWithoutWaitingTakesWhatIsThereAndNothingElse) {
  UdpTransport a({"127.0.0.1", 0}, {"127.0.0.1", 9});
  UdpTransport b({"127.0.0.1", 0}, {"127.0.0.1", a.local_port()});
  a.set_peer({"127.0.0.1", b.local_port()});
  std::array<std::uint8_t, 64> buffer{};
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(a.receive(buffer, 0us).has_value());
  const std::array<std::uint8_t, 3> hello{1, 2, 3};
  ASSERT_TRUE(b.send(hello));
  ASSERT_TRUE(b.send(hello));
  EXPECT_EQ(a.receive(buffer, 0us), std::optional<std::size_t>(3));
  EXPECT_EQ(a.receive(buffer, 0us), std::optional<std::size_t>(3));
  EXPECT_FALSE(a.receive(buffer, 0us).has_value());
  // Waiting again works after the non-blocking reads.
  ASSERT_TRUE(b.send(hello));
  EXPECT_EQ(a.receive(buffer, 100ms), std::optional<std::size_t>(3));
  EXPECT_FALSE(a.receive(buffer, 1ms).has_value());
  EXPECT_LT(std::chrono::steady_clock::now() - start, 1s);
}

TEST(UdpTransport, DatagramsFromOthersAreDropped) {
  UdpTransport a({"127.0.0.1", 0}, {"127.0.0.1", 9});
  UdpTransport stranger({"127.0.0.1", 0}, {"127.0.0.1", a.local_port()});
  const std::array<std::uint8_t, 3> hello{1, 2, 3};
  ASSERT_TRUE(stranger.send(hello));
  std::array<std::uint8_t, 64> buffer{};
  EXPECT_FALSE(a.receive(buffer, 0us).has_value());
  ASSERT_TRUE(stranger.send(hello));
  EXPECT_FALSE(a.receive(buffer, 20ms).has_value());
}

}  // namespace
}  // namespace safecell
