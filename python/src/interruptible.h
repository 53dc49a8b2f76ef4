// Long work that Ctrl-C stops: the work runs on a worker thread with the GIL released while this
// thread checks Python's signals (PyErr_CheckSignals runs handlers only on the main thread, and
// only while it holds the GIL), so a KeyboardInterrupt sets the work's cancel flag, the worker
// stops within its own cancel granularity, and the interrupt propagates.
#pragma once

#include <atomic>
#include <functional>

namespace obscura::python {

// Runs `work(cancel)` to its end, or until a signal handler raises: then `cancel` is set, the
// worker is joined and the Python exception (KeyboardInterrupt for Ctrl-C) is thrown as
// py::error_already_set. An exception the work throws is rethrown here. Called with the GIL held.
void run_interruptible(const std::function<void(const std::atomic<bool>& cancel)>& work);

}  // namespace obscura::python
