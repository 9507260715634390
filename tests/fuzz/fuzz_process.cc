// Running the product: fork, exec, wait with a timeout, kill the process group, collect the outputs.
#include "fuzz_process.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <thread>

namespace fuzz
{
  namespace
  {
    /// One attempt; false when execv itself failed (errno in `exec_error').
    bool attempt(const std::vector<std::string> &argv, const fs::path &cwd, double timeout, Outcome &o, int &exec_error)
    {
      // everything the child needs is prepared before fork: after it, only async-signal-safe calls
      std::vector<char *> args;
      for (const auto &a : argv)
        args.push_back(const_cast<char *>(a.c_str()));
      args.push_back(nullptr);
      const std::string dir = cwd.string(), out_path = (cwd / "stdout.txt").string(),
                        err_path = (cwd / "stderr.txt").string();

      // a close-on-exec pipe tells the parent whether execv itself failed (a binary being relinked):
      // that is the driver's problem, not an exit code of the product
      int exec_pipe[2];
      if (pipe2(exec_pipe, O_CLOEXEC) != 0)
        {
          std::perror("fuzz_inputs: pipe2");
          std::exit(2);
        }
      const auto start = std::chrono::steady_clock::now();
      const pid_t pid = fork();
      if (pid < 0)
        {
          std::perror("fuzz_inputs: fork");
          std::exit(2);
        }
      if (pid == 0)
        {
          setpgid(0, 0);
          const int in = open("/dev/null", O_RDONLY);
          const int out = open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
          const int err = open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
          if (in >= 0 && out >= 0 && err >= 0 && chdir(dir.c_str()) == 0)
            {
              dup2(in, 0), dup2(out, 1), dup2(err, 2);
              execv(args[0], args.data());
            }
          const int error = errno;
          (void)!write(exec_pipe[1], &error, sizeof(error));
          _exit(127);
        }
      setpgid(pid, pid); // also here: whichever of parent and child comes first
      close(exec_pipe[1]);
      const bool exec_failed = read(exec_pipe[0], &exec_error, sizeof(exec_error)) == sizeof(exec_error);
      close(exec_pipe[0]);
      if (exec_failed)
        {
          waitpid(pid, nullptr, 0);
          return false;
        }

      o = Outcome();
      int status = 0;
      for (;;)
        {
          const pid_t r = waitpid(pid, &status, WNOHANG);
          if (r == pid)
            break;
          if (r < 0 && errno != EINTR)
            break;
          const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          if (elapsed > timeout)
            {
              o.timed_out = true;
              kill(-pid, SIGKILL);
              waitpid(pid, &status, 0);
              break;
            }
          std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
      kill(-pid, SIGKILL); // stragglers of the group, if any (ESRCH otherwise)
      o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (!o.timed_out)
        {
          if (WIFEXITED(status))
            o.exit_code = WEXITSTATUS(status);
          else if (WIFSIGNALED(status))
            o.signal = WTERMSIG(status);
        }
      o.out = read_file(out_path);
      o.err = read_file(err_path);
      return true;
    }
  } // namespace

  Outcome run_process(const std::vector<std::string> &argv, const fs::path &cwd, double timeout)
  {
    // the binary is relinked by builds beside us (EACCES, ETXTBSY, ENOENT for a while): wait for it, up
    // to ten minutes, rather than end a long fuzz session over it; any other failure is the driver's
    Outcome o;
    int exec_error = 0;
    for (int tries = 0; !attempt(argv, cwd, timeout, o, exec_error); ++tries)
      {
        if (tries == 300 || (exec_error != EACCES && exec_error != ETXTBSY && exec_error != ENOENT))
          {
            std::cerr << "fuzz_inputs: cannot execute " << argv[0] << ": " << std::strerror(exec_error) << "\n";
            std::exit(2);
          }
        if (tries == 0)
          std::cout << "note: cannot execute " << argv[0] << " (" << std::strerror(exec_error)
                    << "): waiting for the build beside us" << std::endl;
        std::this_thread::sleep_for(std::chrono::seconds(2));
      }
    return o;
  }
} // namespace fuzz
