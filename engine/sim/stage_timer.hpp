#pragma once
// Wall-clock time spent in each named stage of the step, for the end-of-run summary and the
// benchmarks. Stages appear in the order they first ran.
#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace washout {

class StageTimer {
 public:
  using Clock = std::chrono::steady_clock;

  class Scope {
   public:
    Scope(StageTimer& timer, std::size_t slot) : timer_(timer), slot_(slot), start_(Clock::now()) {}
    ~Scope() {
      timer_.totals_[slot_].second += std::chrono::duration<double>(Clock::now() - start_).count();
    }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    StageTimer& timer_;
    std::size_t slot_;
    Clock::time_point start_;
  };

  Scope measure(const std::string& stage) {
    for (std::size_t k = 0; k < totals_.size(); ++k)
      if (totals_[k].first == stage) return Scope(*this, k);
    totals_.emplace_back(stage, 0.0);
    return Scope(*this, totals_.size() - 1);
  }
  const std::vector<std::pair<std::string, double>>& totals() const { return totals_; }
  double total() const {
    double s = 0;
    for (const auto& t : totals_) s += t.second;
    return s;
  }

 private:
  std::vector<std::pair<std::string, double>> totals_;
};

}  // namespace washout
