// Protocol lines written straight from a world's doubles, for traces of any size (`circles run --trace`).
//
// A line is {"<counter>":N,"circles":[[px,py,vx,vy,r],...]} and its newline: the bytes of append_line
// (formats/protocol.hpp), each number json_number::write's shortest round-trip text. LineWriter never holds a
// line whole: it reads the circles a part of kPartCircles at a time into a buffer of its own, formats the part
// into another, and hands the text to the sink in order. Parts are formatted on several threads at once, each
// thread with its own two buffers, and handed over in the order of the circles, so the bytes are the same for
// every thread count. Memory is those buffers, about threads × kPartCircles × (40 + kMaxCircleChars) bytes,
// whatever the world's size.
#pragma once

#include "formats/json_number.hpp"
#include "formats/protocol.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

namespace circles::formats {

// A world read a slice at a time: source(first, out) sets out[i] to circle first + i, [px, py, vx, vy, r].
// LineWriter calls it from several threads at once, on slices that do not overlap.
using CircleSource = std::function<void(std::size_t first, std::span<spec::CircleDoubles> out)>;

// The source of a world held whole.
CircleSource source_of(const Circles& circles);

// Where a line's text goes, a piece at a time, in order: OutputFile::write for a trace. It may throw; the
// exception leaves LineWriter::write after every thread has stopped.
using TextSink = std::function<void(std::string_view text)>;

// A circle's text at most: ",[" then five numbers of json_number::kMaxChars with four commas between, then "]".
inline constexpr std::size_t kMaxCircleChars = 2 + 5 * json_number::kMaxChars + 4 + 1;

// Circles per part: a part's text is at most 8192 × 137 bytes, about 1.1 MB, big enough that handing it over
// costs one write, small enough that every thread's buffers stay in a few MB.
inline constexpr std::size_t kPartCircles = 8192;

class LineWriter {
 public:
  // Formats on up to `threads` threads (0: one per core).
  explicit LineWriter(unsigned threads = 1);

  // Writes the line of `circles` circles read through `source`, with its newline, to `sink`; returns its
  // bytes. Throws std::domain_error for a number that is not finite (as append_line does) and whatever the
  // source or the sink throws, the first in the order of the parts, once every thread has stopped; the parts
  // before it have reached the sink, none after it.
  std::uint64_t write(const TextSink& sink, std::string_view counter, std::uint64_t number, std::size_t circles,
                      const CircleSource& source);

  unsigned threads() const noexcept { return threads_; }

 private:
  struct Buffers {
    Circles circles;
    std::vector<char> text;
  };
  unsigned threads_;
  std::vector<Buffers> buffers_;  // one per thread, kept from line to line
};

}  // namespace circles::formats
