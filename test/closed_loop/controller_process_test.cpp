// The controller program never outlives the process that started it: a parent killed with
// SIGKILL (no destructor runs) still takes its child with it. /bin/sleep stands in for
// safecell-controller: what is tested is the process relation, not the program.

#include "safecell/closed_loop/controller_process.hpp"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace safecell {
namespace {

// Gone, or a zombie waiting for a reaper: no longer running either way.
bool running(int pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string pid_text;
  std::string name;
  char state = 'X';
  if (!(stat >> pid_text >> name >> state)) return false;
  return state != 'Z' && state != 'X';
}

TEST(ControllerProcess, TheProgramDiesWithAParentKilledWithoutWarning) {
  const auto log = std::filesystem::path(::testing::TempDir()) /
                   ("safecell-process-" + std::to_string(::getpid()) + ".log");
  int pipe_fds[2];
  ASSERT_EQ(::pipe(pipe_fds), 0);
  const pid_t parent = ::fork();
  ASSERT_GE(parent, 0);
  if (parent == 0) {  // the parent to be killed: starts the program, says its id, waits
    ::close(pipe_fds[0]);
    ControllerProcess process("/bin/sleep", {"60"}, log);
    const int child = process.pid();
    if (::write(pipe_fds[1], &child, sizeof child) != sizeof child) ::_exit(1);
    for (;;) ::pause();
  }
  ::close(pipe_fds[1]);
  int child = 0;
  ASSERT_EQ(::read(pipe_fds[0], &child, sizeof child), static_cast<ssize_t>(sizeof child));
  ::close(pipe_fds[0]);
  ASSERT_TRUE(running(child));
  ::kill(parent, SIGKILL);
  ::waitpid(parent, nullptr, 0);
  const auto start = std::chrono::steady_clock::now();
  while (running(child) && std::chrono::steady_clock::now() - start < std::chrono::seconds(10)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  const bool outlived = running(child);
  if (outlived) ::kill(child, SIGKILL);
  EXPECT_FALSE(outlived) << "the program ran on 10 s after its parent was killed";
  std::filesystem::remove(log);
}

}  // namespace
}  // namespace safecell
