#include "formats/trace_writer.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cmath>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

namespace circles::formats {

CircleSource source_of(const Circles& circles) {
  return [&circles](std::size_t first, std::span<spec::CircleDoubles> out) {
    std::copy_n(circles.begin() + static_cast<std::ptrdiff_t>(first), out.size(), out.begin());
  };
}

LineWriter::LineWriter(unsigned threads)
    : threads_(threads != 0 ? threads : std::max(std::thread::hardware_concurrency(), 1u)) {}

namespace {

// The text of circles [first, first + in.size()) at `out`, which has room for in.size() × kMaxCircleChars
// characters: each circle ",[px,py,vx,vy,r]", without the comma for circle 0. Returns its end, or nullptr at
// the first number that is not finite.
char* format_part(char* out, std::size_t first, std::span<const spec::CircleDoubles> in) {
  for (std::size_t i = 0; i < in.size(); ++i) {
    if (first + i != 0) *out++ = ',';
    *out++ = '[';
    for (std::size_t j = 0; j < 5; ++j) {
      if (!std::isfinite(in[i][j])) return nullptr;
      if (j != 0) *out++ = ',';
      out = json_number::write(out, in[i][j]);
    }
    *out++ = ']';
  }
  return out;
}

}  // namespace

std::uint64_t LineWriter::write(const TextSink& sink, std::string_view counter, std::uint64_t number,
                                std::size_t circles, const CircleSource& source) {
  std::string text = "{\"";
  text += counter;
  text += "\":";
  text += std::to_string(number);
  text += ",\"circles\":[";
  sink(text);
  std::uint64_t bytes = text.size();

  const std::size_t parts = (circles + kPartCircles - 1) / kPartCircles;
  const unsigned threads = static_cast<unsigned>(std::clamp<std::size_t>(parts, 1, threads_));
  if (buffers_.size() < threads) buffers_.resize(threads);
  // Worker w of `workers` (OpenMP's threads, those the engines step on: started already, and busy here instead
  // of spinning idle beside the formatting) formats parts w, w + workers, ... into its own buffers and hands
  // each to the sink at its turn, part 0 first: a worker formats its next part while another hands its own
  // over. A worker waits for its turn asleep on a condition variable, not spinning (OpenMP's ordered loop
  // spins by default, which on a machine with no free core took the core the formatting needed). The first
  // failure in part order is kept (only the worker whose turn it is writes `error`) and ends the work of every
  // later part.
  std::exception_ptr error;
  std::atomic<bool> failed = false;
  std::mutex turns;
  std::condition_variable next;
  std::size_t turn = 0;       // the part whose text goes to the sink next
  const auto work = [&](std::size_t w, std::size_t workers) {
    Buffers& own = buffers_[w];
    for (std::size_t p = w; p < parts; p += workers) {
      const std::size_t first = p * kPartCircles;
      const std::size_t n = std::min(kPartCircles, circles - first);
      const char* end = nullptr;
      std::exception_ptr own_error;
      if (!failed.load(std::memory_order_relaxed)) {
        try {
          own.circles.resize(kPartCircles);
          own.text.resize(kPartCircles * kMaxCircleChars);
          const std::span<spec::CircleDoubles> in(own.circles.data(), n);
          source(first, in);
          end = format_part(own.text.data(), first, in);
          if (!end) throw std::domain_error("a JSON number must be finite");
        } catch (...) {
          own_error = std::current_exception();
        }
      }
      {
        std::unique_lock lock(turns);
        next.wait(lock, [&] { return turn == p; });
      }
      if (!error) {
        try {
          if (own_error) std::rethrow_exception(own_error);
          sink(std::string_view(own.text.data(), static_cast<std::size_t>(end - own.text.data())));
          bytes += static_cast<std::uint64_t>(end - own.text.data());
        } catch (...) {
          error = std::current_exception();
          failed = true;
        }
      }
      {
        const std::lock_guard lock(turns);
        ++turn;
      }
      next.notify_all();
    }
  };
#pragma omp parallel num_threads(threads) if (threads > 1)
  work(static_cast<std::size_t>(omp_get_thread_num()), static_cast<std::size_t>(omp_get_num_threads()));
  if (error) std::rethrow_exception(error);
  text = "]}\n";
  sink(text);
  return bytes + text.size();
}

}  // namespace circles::formats
