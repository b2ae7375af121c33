// An output that replaces an existing file respects it: a file the user may not write, or one
// with other hard links, is refused before any work and left as it was; any other keeps its
// mode, and its owner and group where clrt may set them.
#include <grp.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <functional>
#include <optional>
#include <string>

#include "image/image.hpp"
#include "image/output_target.hpp"
#include "skip_test.hpp"
#include "test_files.hpp"

using clrt::Rgba8Image;
using namespace clrt::test;
using Entries = std::set<std::string>;

namespace {

const Rgba8Image kOld{1, 1, {{1, 2, 3, 255}}};
const Rgba8Image kNew{2, 1, {{4, 5, 6, 255, 7, 8, 9, 255}}};
constexpr uid_t kNobody = 65534;

struct stat stat_of(const std::string& path) {
  struct stat info {};
  REQUIRE(::stat(path.c_str(), &info) == 0);
  return info;
}

// `step`'s ImageError message, or "", as an ordinary user: the test's own user, or nobody
// (uid and gid 65534) in a child when the tests run as root, whom permission bits do not bind.
// Nothing when root cannot become nobody.
std::optional<std::string> as_ordinary_user(const std::function<void()>& step) {
  if (::geteuid() != 0) return error_of(step);
  int pipe_ends[2];
  REQUIRE(::pipe(pipe_ends) == 0);
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    ::close(pipe_ends[0]);
    if (::setgroups(0, nullptr) != 0 || ::setgid(kNobody) != 0 || ::setuid(kNobody) != 0)
      ::_exit(3);
    const std::string error = error_of(step);
    const bool written = ::write(pipe_ends[1], error.data(), error.size()) ==
                         static_cast<ssize_t>(error.size());
    ::_exit(written ? 0 : 4);
  }
  ::close(pipe_ends[1]);
  std::string error;
  char buffer[256];
  for (ssize_t got; (got = ::read(pipe_ends[0], buffer, sizeof buffer)) > 0;)
    error.append(buffer, static_cast<std::size_t>(got));
  ::close(pipe_ends[0]);
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  REQUIRE(WIFEXITED(status));
  if (WEXITSTATUS(status) == 3) return std::nullopt;
  REQUIRE(WEXITSTATUS(status) == 0);
  return error;
}

// A scratch folder that nobody, too, may create files in.
void open_to_all(const ScratchDir& dir) {
  REQUIRE(::chmod(dir.path().c_str(), 0777) == 0);
}

// `path` written with kOld, then given `mode` and, as root, nobody's ownership.
void write_old(const std::string& path, mode_t mode) {
  clrt::write_image(path, kOld);
  if (::geteuid() == 0) REQUIRE(::chown(path.c_str(), kNobody, kNobody) == 0);
  REQUIRE(::chmod(path.c_str(), mode) == 0);
}

}  // namespace

TEST_CASE("an existing output the user may not write is refused before any work, and kept",
          "[image][output][replace]") {
  ScratchDir dir;
  open_to_all(dir);
  const std::string path = dir.file("ro.png");
  write_old(path, 0444);
  const Bytes before = read_bytes(path);
  const std::string refused = "cannot write " + path + ": it is read-only to you (mode 0444)";
  const auto checked = as_ordinary_user([&] { clrt::check_output_writable(path); });
  if (!checked) CLRT_SKIP_TEST("root cannot become nobody (uid 65534) here");
  CHECK(*checked == refused);
  CHECK(as_ordinary_user([&] { clrt::write_image(path, kNew); }) == refused);
  CHECK(read_bytes(path) == before);
  CHECK((stat_of(path).st_mode & 07777) == 0444);
  CHECK(dir.entries() == Entries{"ro.png"});
  if (::geteuid() == 0) {
    // Root writes a read-only file with a shell's `>`, and may replace it here too.
    CHECK(error_of([&] { clrt::check_output_writable(path); }).empty());
    clrt::write_image(path, kNew);
    CHECK(clrt::read_image(path).frames == kNew.frames);
    CHECK((stat_of(path).st_mode & 07777) == 0444);
  }
}

TEST_CASE("a replaced file keeps its mode, and its owner and group where clrt may set them",
          "[image][output][replace]") {
  ScratchDir dir;
  open_to_all(dir);
  for (const mode_t mode : {mode_t{0600}, mode_t{0640}, mode_t{0664}}) {
    INFO(mode);
    const std::string path = dir.file("out.png");
    write_old(path, mode);
    const struct stat before = stat_of(path);
    clrt::write_image(path, kNew);
    const struct stat after = stat_of(path);
    CHECK(clrt::read_image(path).frames == kNew.frames);
    CHECK(after.st_ino != before.st_ino);  // replaced whole, not written in place
    CHECK((after.st_mode & 07777) == mode);
    CHECK(after.st_uid == before.st_uid);  // nobody's, when root wrote it
    CHECK(after.st_gid == before.st_gid);
    CHECK(dir.entries() == Entries{"out.png"});
  }
  // An ordinary user cannot give the file away: it keeps the mode and becomes the user's.
  const std::string theirs = dir.file("theirs.png");
  write_old(theirs, 0666);
  if (::geteuid() == 0) REQUIRE(::chown(theirs.c_str(), 0, 0) == 0);
  const auto replaced = as_ordinary_user([&] { clrt::write_image(theirs, kNew); });
  if (!replaced) CLRT_SKIP_TEST("root cannot become nobody (uid 65534) here");
  CHECK(replaced->empty());
  CHECK((stat_of(theirs).st_mode & 07777) == 0666);
  CHECK(stat_of(theirs).st_uid == (::geteuid() == 0 ? kNobody : ::geteuid()));
}

TEST_CASE("an output with other hard links is refused before any work, and every name kept",
          "[image][output][replace]") {
  ScratchDir dir;
  const std::string path = dir.file("a.png"), other = dir.file("b.png");
  clrt::write_image(path, kOld);
  REQUIRE(::link(path.c_str(), other.c_str()) == 0);
  const std::string refused = "cannot write " + path +
                              ": it has 2 hard links, and replacing it would leave the others "
                              "with the old image; remove this name first, or write another";
  CHECK(error_of([&] { clrt::check_output_writable(path); }) == refused);
  CHECK(error_of([&] { clrt::write_image(path, kNew); }) == refused);
  // Through a symbolic link, the file it points to is what would be replaced.
  const std::string link = dir.file("link.png");
  REQUIRE(::symlink(path.c_str(), link.c_str()) == 0);
  CHECK(error_of([&] { clrt::check_output_replaceable(link); }) ==
        "cannot write " + link + ": it has 2 hard links, and replacing it would leave the "
                                 "others with the old image; remove this name first, or write "
                                 "another");
  CHECK(clrt::read_image(path).frames == kOld.frames);
  CHECK(stat_of(path).st_ino == stat_of(other).st_ino);
  CHECK(dir.entries() == Entries{"a.png", "b.png", "link.png"});
  // Once the other name is gone, the file is replaced as any other.
  REQUIRE(::unlink(other.c_str()) == 0);
  clrt::write_image(path, kNew);
  CHECK(clrt::read_image(path).frames == kNew.frames);
}
