#include "conform/serve.hpp"

#include "formats/protocol.hpp"
#include "impl/overflow.hpp"  // impl::overflow_reason

#include <istream>
#include <ostream>

namespace circles::conform {

RequestOverflow::RequestOverflow(std::size_t l, std::uint64_t i, std::size_t k, spec::Field f)
    : std::overflow_error("line " + std::to_string(l) + " (id " + std::to_string(i) + "): " + impl::overflow_reason(k, f)),
      line(l),
      id(i),
      index(k),
      field(f) {}

namespace {

StepFunction engine_step(const engines::EngineEntry& engine, unsigned threads) {
  return [&engine, threads](const Circles& w) { return engines::step_once(engine, w, threads); };
}

}  // namespace

std::string answer(const StepFunction& step, std::string_view request, std::size_t line_number) {
  const Line in = parse_line(request, line_number);
  try {
    return format_line(kId, in.number, step(in.circles));
  } catch (const engines::StepOverflow& e) {
    throw RequestOverflow(line_number, in.number, e.index, e.field);
  }
}

std::string answer(const engines::EngineEntry& engine, unsigned threads, std::string_view request, std::size_t line_number) {
  return answer(engine_step(engine, threads), request, line_number);
}

int serve(const engines::EngineEntry& engine, unsigned threads, std::istream& in, std::ostream& out, std::ostream& err) {
  return serve(engine_step(engine, threads), in, out, err);
}

int serve(const StepFunction& step, std::istream& in, std::ostream& out, std::ostream& err) {
  std::string request;
  for (std::size_t line = 1; std::getline(in, request); ++line) {
    try {
      out << answer(step, request, line) << '\n' << std::flush;
      if (!out) {
        err << "circles serve: cannot write the response to line " << line << "\n";
        return 2;
      }
    } catch (const ProtocolError& e) {
      err << "circles serve: malformed request, " << e.what() << "\n";
      return 2;
    } catch (const RequestOverflow& e) {
      err << "circles serve: " << e.what()
          << "; the step of this request has no finite image in doubles, so there is no response to write\n";
      return 2;
    }
  }
  return 0;
}

}  // namespace circles::conform
