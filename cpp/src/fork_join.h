// Internal: two-way fork-join for the passes over a whole mesh (Triangle, the peer, runs on one core; the
// machines this targets have two or more).
#pragma once
#include <cstddef>
#include <exception>
#include <system_error>
#include <thread>

namespace nonobtuse {

// Whether a pass over `size` items (faces, triangles) with `threads` allowed is worth a second thread: starting
// one costs tens of microseconds, so only from 2^16 items.
inline bool worth_forking(std::size_t size, int threads) { return threads >= 2 && size >= (std::size_t{1} << 16); }

// Runs a() on a second thread and b() on this one when `parallel` (and a thread can be started), else a() then
// b(); returns when both are done. An exception is rethrown after both finished, a()'s before b()'s, so the error
// reported does not depend on timing and is the one the sequential order reports.
template <class A, class B>
void fork_join(bool parallel, A&& a, B&& b) {
  std::exception_ptr ea, eb;
  std::thread t;
  if (parallel) {
    try {
      t = std::thread([&] {
        try {
          a();
        } catch (...) {
          ea = std::current_exception();
        }
      });
    } catch (const std::system_error&) {
      parallel = false;
    }
  }
  if (!parallel) {
    a();
    b();
    return;
  }
  try {
    b();
  } catch (...) {
    eb = std::current_exception();
  }
  t.join();
  if (ea) std::rethrow_exception(ea);
  if (eb) std::rethrow_exception(eb);
}

}  // namespace nonobtuse
