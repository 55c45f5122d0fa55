// SIGINT and SIGTERM routed to one handler for the lifetime of a command that runs several simulations
// (ballistic-limit, sweep) or one run (driver.cpp); the previous handlers come back when it ends.
#pragma once
#include <csignal>

namespace impactsph {

class ScopedSignals {
 public:
  explicit ScopedSignals(void (*handler)(int))
      : old_int_(std::signal(SIGINT, handler)), old_term_(std::signal(SIGTERM, handler)) {}
  ~ScopedSignals() {
    std::signal(SIGINT, old_int_);
    std::signal(SIGTERM, old_term_);
  }
  ScopedSignals(const ScopedSignals&) = delete;
  ScopedSignals& operator=(const ScopedSignals&) = delete;

 private:
  void (*old_int_)(int);
  void (*old_term_)(int);
};

}  // namespace impactsph
