#include "core/process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>

#include "core/error.h"

namespace hipr {
namespace {

struct Pipe {
  int fd[2] = {-1, -1};
  Pipe() {
    if (pipe2(fd, O_CLOEXEC) != 0) throw InternalError("cannot create a pipe");
  }
  ~Pipe() { close_both(); }
  void close_end(int i) {
    if (fd[i] >= 0) close(fd[i]);
    fd[i] = -1;
  }
  void close_both() {
    close_end(0);
    close_end(1);
  }
};

}  // namespace

ProcessResult run_process(const std::vector<std::string>& argv, std::string_view input) {
  if (argv.empty()) throw InternalError("run_process needs a program");
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  Pipe in, out;
  const pid_t pid = fork();
  if (pid < 0) throw InternalError("cannot start " + argv[0]);
  if (pid == 0) {
    dup2(in.fd[0], STDIN_FILENO);
    dup2(out.fd[1], STDOUT_FILENO);
    dup2(out.fd[1], STDERR_FILENO);
    execvp(args[0], args.data());
    _exit(127);
  }
  in.close_end(0);
  out.close_end(1);
  // Feed stdin and drain stdout together, so neither side blocks on a full pipe.
  ProcessResult result;
  size_t written = 0;
  fcntl(in.fd[1], F_SETFL, O_NONBLOCK);
  if (input.empty()) in.close_end(1);
  const sighandler_t previous =
      signal(SIGPIPE, SIG_IGN);  // a child that exits early must not kill us
  while (out.fd[0] >= 0) {
    pollfd fds[2] = {{out.fd[0], POLLIN, 0}, {in.fd[1], POLLOUT, 0}};
    const int n = poll(fds, in.fd[1] >= 0 ? 2 : 1, -1);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    if (in.fd[1] >= 0 && (fds[1].revents & (POLLOUT | POLLERR | POLLHUP))) {
      const ssize_t w = write(in.fd[1], input.data() + written, input.size() - written);
      if (w > 0) written += size_t(w);
      if (w < 0 && errno != EAGAIN) in.close_end(1);
      if (written == input.size()) in.close_end(1);
    }
    if (fds[0].revents & (POLLIN | POLLHUP | POLLERR)) {
      char buffer[4096];
      const ssize_t r = read(out.fd[0], buffer, sizeof buffer);
      if (r > 0)
        result.output.append(buffer, size_t(r));
      else if (r == 0 || errno != EINTR)
        out.close_end(0);
    }
  }
  signal(SIGPIPE, previous);
  // Closing our read end too: a child still writing after a failed poll gets EPIPE instead of
  // blocking on a full pipe while we wait for it.
  in.close_both();
  out.close_both();
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.exit_code =
      WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  return result;
}

}  // namespace hipr
