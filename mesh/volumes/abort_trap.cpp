// runTrappingAbort: SIGABRT caught during one call and turned into a jump back to its caller.
#include "mesh/volumes/abort_trap.h"

#include <fcntl.h>
#include <unistd.h>

#include <csetjmp>
#include <csignal>
#include <cstdio>

// In sanitizer builds, what an aborted call leaves allocated is a known, accepted leak: the
// leak checker is told to ignore what is allocated during the call.
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(leak_sanitizer)
#define GEOMESH_LEAK_CHECKER 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define GEOMESH_LEAK_CHECKER 1
#endif
#ifdef GEOMESH_LEAK_CHECKER
extern "C" void __lsan_disable();
extern "C" void __lsan_enable();
#endif

namespace geomesh {
namespace {

// Allocations made during its lifetime are not reported as leaks (sanitizer builds only).
class LeaksIgnored {
 public:
  LeaksIgnored() {
#ifdef GEOMESH_LEAK_CHECKER
    __lsan_disable();
#endif
  }
  ~LeaksIgnored() {
#ifdef GEOMESH_LEAK_CHECKER
    __lsan_enable();
#endif
  }
  LeaksIgnored(const LeaksIgnored&) = delete;
  LeaksIgnored& operator=(const LeaksIgnored&) = delete;
};

// Where the handler jumps: a signal handler can only reach state that is not on the stack.
thread_local sigjmp_buf* activeJump = nullptr;

extern "C" void jumpBackOnAbort(int) {
  if (activeJump) siglongjmp(*activeJump, 1);
}

// Installs the handler for the lifetime of one call, and restores what was there before.
class AbortHandler {
 public:
  explicit AbortHandler(sigjmp_buf& jump) {
    struct sigaction action {};
    action.sa_handler = jumpBackOnAbort;
    sigemptyset(&action.sa_mask);
    sigaction(SIGABRT, &action, &previous_);
    activeJump = &jump;
  }
  ~AbortHandler() {
    activeJump = nullptr;
    sigaction(SIGABRT, &previous_, nullptr);
  }
  AbortHandler(const AbortHandler&) = delete;
  AbortHandler& operator=(const AbortHandler&) = delete;

 private:
  struct sigaction previous_ {};
};

// Sends the standard error to /dev/null for its lifetime: the message of a failed assertion,
// printed before the abort, would read as a crash report although the caller goes on.
class SilencedStderr {
 public:
  SilencedStderr() : saved_(dup(STDERR_FILENO)) {
    const int null = open("/dev/null", O_WRONLY);
    if (saved_ >= 0 && null >= 0) {
      std::fflush(stderr);
      dup2(null, STDERR_FILENO);
    }
    if (null >= 0) close(null);
  }
  ~SilencedStderr() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    dup2(saved_, STDERR_FILENO);
    close(saved_);
  }
  SilencedStderr(const SilencedStderr&) = delete;
  SilencedStderr& operator=(const SilencedStderr&) = delete;

 private:
  int saved_;
};

}  // namespace

bool runTrappingAbort(const std::function<void()>& call) {
  sigjmp_buf jump;
  const AbortHandler handler(jump);
  const SilencedStderr silence;
  const LeaksIgnored leaks;
  // sigsetjmp saves the signal mask, so that SIGABRT, blocked while its handler runs, is
  // unblocked again after the jump.
  if (sigsetjmp(jump, 1) != 0) return false;
  call();
  return true;
}

}  // namespace geomesh
