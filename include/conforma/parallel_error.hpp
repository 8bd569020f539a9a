#pragma once
// An exception may not leave an OpenMP parallel loop (it terminates the process: a bad option validated inside the
// Manchester loop aborted the Python interpreter, session 25). The loops catch it per iteration and record it here;
// after the loop the error of the lowest iteration index is rethrown, so the message is the same for any thread
// count.
#include <exception>
#include <mutex>
#include <string>

namespace conforma {

class LowestIndexError {
 public:
  // Keeps e.what() when `index` is lower than any recorded before. Thread-safe.
  void Record(long index, const std::exception& e) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (index_ < 0 || index < index_) index_ = index, what_ = e.what();
  }
  bool any() const { return index_ >= 0; }  // (after the loop)
  long index() const { return index_; }
  const std::string& what() const { return what_; }

 private:
  std::mutex mutex_;
  long index_ = -1;
  std::string what_;
};

}  // namespace conforma
