#include "interruptible.h"

#include <pybind11/pybind11.h>

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

namespace obscura::python {

namespace py = pybind11;

namespace {
// How often the signals are checked: short enough that Ctrl-C feels immediate.
constexpr auto kSignalSlice = std::chrono::milliseconds(50);
}  // namespace

void run_interruptible(const std::function<void(const std::atomic<bool>& cancel)>& work) {
  std::atomic<bool> cancel{false};
  std::mutex mutex;
  std::condition_variable finished_signal;
  bool finished = false;
  std::exception_ptr error;
  std::thread worker([&] {
    try {
      work(cancel);
    } catch (...) {
      error = std::current_exception();
    }
    std::lock_guard lock(mutex);
    finished = true;
    finished_signal.notify_all();
  });
  std::optional<py::error_already_set> interrupted;
  for (bool done = false; !done;) {
    {
      py::gil_scoped_release release;
      std::unique_lock lock(mutex);
      done = finished_signal.wait_for(lock, kSignalSlice, [&] { return finished; });
    }
    if (!done && !interrupted && PyErr_CheckSignals() != 0) {
      interrupted.emplace();
      cancel = true;
    }
  }
  {
    py::gil_scoped_release release;
    worker.join();
  }
  if (interrupted) throw std::move(*interrupted);
  if (error) std::rethrow_exception(error);
}

}  // namespace obscura::python
