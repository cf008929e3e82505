// runTrappingAbort: SIGABRT caught during one call and turned into a jump back to its caller.
#include "mesh/volumes/abort_trap.h"

#include <csetjmp>
#include <csignal>

namespace geomesh {
namespace {

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

}  // namespace

bool runTrappingAbort(const std::function<void()>& call) {
  sigjmp_buf jump;
  const AbortHandler handler(jump);
  // sigsetjmp saves the signal mask, so that SIGABRT, blocked while its handler runs, is
  // unblocked again after the jump.
  if (sigsetjmp(jump, 1) != 0) return false;
  call();
  return true;
}

}  // namespace geomesh
