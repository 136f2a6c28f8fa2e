// The fast path of the readers of big documents, scenes and trace lines: a document whose circles are in the
// compact form, {... "circles": [[px, py, vx, vy, r], ...] ...}, read from a stream in pieces, so that reading
// it holds its circles (5 doubles each) and one piece of text, never the whole text nor a DOM of it.
//
// How: the text up to the first `"circles": [` is the head; the circles are cut after a circle's `]` that a
// `,` follows, each piece read as an array by PlainLineReader::append_circles (simdjson On-Demand, the numbers
// as the exact readers read them); the text from the `]` that closes the circles is the tail. What is left,
// head + tail, is the document with "circles": [] (Streamed::outer), small, for the caller's exact reader to
// check whole: its keys, their duplicates, "name", "steps", the step number, anything after the document.
// The caller must also check that the `[` and `]` that were joined are the circles' array and not, say, the
// inside of a string: with one circle put between them (Streamed::with_one_circle) its exact reader must read
// exactly one circle, and without it none.
//
//   Invariant: when stream_document gives a Streamed whose outer and with_one_circle() pass those checks, the
//              exact reader reads the whole document as outer's document with `circles` for its circles, bit
//              for bit. Anything else (the object form of a circle, an integer beyond 64 bits, a number beyond
//              the double range, a negative radius, no circles, malformed text, ...) gives nothing, and the
//              caller reads the text with its exact reader, whose message names the fault.
// fuzz/scene_fuzzer.cpp and fuzz/trace_fuzzer.cpp hold the two paths to the same result on any bytes.
#pragma once

#include "formats/plain_line.hpp"
#include "formats/protocol.hpp"

#include <cstddef>
#include <cstdint>
#include <istream>
#include <optional>
#include <string>

namespace circles::formats {

// The most text outside the circles the fast path takes, head and tail each, and the bytes it reads for the
// head: a scene's or a line's other keys are a few dozen bytes; a document with more is the exact reader's.
inline constexpr std::size_t kMaxOuter = std::size_t{1} << 16;

// The bytes read from the stream at a time: a piece of the circles is at least this much text (but the last).
// 1 MiB: large enough that simdjson's set-up per piece is negligible, small against the circles it holds.
inline constexpr std::size_t kStreamPiece = std::size_t{1} << 20;

struct Streamed {
  std::string outer;       // the document with its circles taken out: "circles": []
  std::size_t junction;    // outer[junction - 1] is the circles' '[', outer[junction] their ']'
  Circles circles;         // the circles, exactly as the document spells them (-0 kept)
  std::uint64_t bytes;     // bytes of the stream the document took, its line's '\n' included

  // outer with the circle [0, 0, 0, 0, 0] between the circles' brackets.
  std::string with_one_circle() const;
};

// Reads one document from `in`: up to its end, or with `line` up to the first '\n' (a line of a trace; `in` may
// then be read beyond that '\n', and the caller moves it back to `bytes` after the start). `piece` is the bytes
// read at a time (smaller in tests and the fuzzer, so that small documents are cut too). Gives nothing for a
// document it does not take, and when a piece of circles grows past 64 pieces without a place to cut.
// `expected` circles are reserved at the start (a trace's lines after the first have as many as the first).
std::optional<Streamed> stream_document(std::istream& in, bool line, PlainLineReader& reader,
                                        std::size_t piece = kStreamPiece, std::size_t expected = 0);

}  // namespace circles::formats
