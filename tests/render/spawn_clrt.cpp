#include "spawn_clrt.hpp"

#include <catch2/catch.hpp>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <stdexcept>

extern char** environ;

namespace clrt::test {

ClrtProcess::ClrtProcess(const std::vector<std::string>& arguments, const std::string& working_dir,
                         const std::vector<std::string>& extra_environment,
                         const std::string& output_file, const std::vector<int>& inherited) {
  std::vector<std::string> args{CLRT_EXE};
  args.insert(args.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_strings(extra_environment);
  for (char** e = environ; *e; ++e) env_strings.emplace_back(*e);
  std::vector<char*> envp;
  for (std::string& e : env_strings) envp.push_back(e.data());
  envp.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, working_dir.c_str());
  posix_spawn_file_actions_addopen(&actions, 1, output_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults;
  sigemptyset(&defaults);
  for (int signal_number : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGALRM, SIGPIPE, SIGUSR1, SIGUSR2,
                            SIGXFSZ})
    sigaddset(&defaults, signal_number);
  for (int signal_number : inherited) sigdelset(&defaults, signal_number);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  const int error = posix_spawn(&pid_, argv[0], &actions, &attributes, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (error != 0) throw std::runtime_error("cannot start " + args[0]);
}

ClrtProcess::~ClrtProcess() {
  if (reaped_) return;
  ::kill(pid_, SIGKILL);
  wait();
}

int ClrtProcess::wait() {
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  reaped_ = true;
  return status;
}

bool ClrtProcess::ended(int& status) {
  if (::waitpid(pid_, &status, WNOHANG) != pid_) return false;
  reaped_ = true;
  return true;
}

std::string read_fifo_line(const std::string& fifo, ClrtProcess& clrt) {
  const int fd = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  REQUIRE(fd >= 0);
  std::string line;
  // The wait has no time limit of its own: it ends when clrt writes, or ends.
  while (line.empty() || line.back() != '\n') {
    pollfd p{fd, POLLIN, 0};
    ::poll(&p, 1, 200);
    char buffer[4096];
    const ssize_t got = ::read(fd, buffer, sizeof buffer);
    if (got > 0) {
      line.append(buffer, static_cast<std::size_t>(got));
      continue;
    }
    int status = 0;
    if (clrt.ended(status)) {
      ::close(fd);
      FAIL("clrt ended before it wrote to " << fifo << ", status " << status);
    }
  }
  ::close(fd);
  line.pop_back();
  return line;
}

}  // namespace clrt::test
