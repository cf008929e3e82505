// runTrappingAbort: a call into a library whose failed assertions abort, turned into a result.
#pragma once

#include <functional>

namespace geomesh {

// Runs `call`; returns false when it aborts (a failed assert() in a library built with
// assertions, as Debian's TetGen is) instead of letting the process die. What the aborted call
// had allocated is leaked, and its objects are left as they were: the caller must drop them.
// Exceptions thrown by `call` pass through. The standard error is discarded during the call
// (the assertion's message would read as a crash report). Not for concurrent use from several
// threads.
bool runTrappingAbort(const std::function<void()>& call);

}  // namespace geomesh
