// faulty_candidate MODE: the correct step (tests/gallery.hpp, no mistake) behind the step protocol, wrong in one
// way on every world of two or more circles, for the tests of what conform makes of answers that are not plain
// numbers and of faults inside a batch of requests (tests/conform_test.cpp):
//   NaN, Infinity, -Infinity   circle 0's px written as that token, as Python's json writes a float that is not
//                              finite;
//   wrong-then-malformed       circle 0's px one ulp up, and then the answer to the next request a line that is
//                              not JSON ("oops"), so that the answers to the rest of conform's batch are still
//                              on their way when it reads the fault;
//   wrong-then-crash           circle 0's px one ulp up, and then exit 3 on the next request.
//   extra-key                  no mistake, but every answer carries a key "ms" beside "id" and "circles".
//   abort K, hang K, garble K  no mistake on worlds of fewer than K circles; on one of K or more, abort()
//                              (killed by SIGABRT), sleep for an hour, or write a line that is not JSON.
// Exits 2 for another MODE.
#include "formats/protocol.hpp"
#include "tests/gallery.hpp"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <thread>

int main(int argc, char** argv) {
  using namespace circles::formats;
  const std::string mode = argc >= 2 ? argv[1] : "";
  const bool token = mode == "NaN" || mode == "Infinity" || mode == "-Infinity";
  const bool at_size = (mode == "abort" || mode == "hang" || mode == "garble") && argc == 3;
  const std::size_t size = at_size ? std::stoul(argv[2]) : 0;
  if (!token && !at_size && mode != "wrong-then-malformed" && mode != "wrong-then-crash" && mode != "extra-key") {
    std::cerr << "faulty_candidate: expected one of NaN, Infinity, -Infinity, wrong-then-malformed, "
                 "wrong-then-crash, extra-key\n";
    return 2;
  }
  bool fault_next = false;
  std::string text;
  for (std::size_t n = 1; std::getline(std::cin, text); ++n) {
    if (fault_next && mode == "wrong-then-crash") return 3;
    if (fault_next) {
      std::cout << "oops" << std::endl;
      fault_next = false;
      continue;
    }
    const Line request = parse_line(text, n);
    if (at_size && request.circles.size() >= size) {
      if (mode == "abort") std::abort();
      if (mode == "hang") std::this_thread::sleep_for(std::chrono::hours(1));
      std::cout << "{\"id\": " << request.number << ", \"circles\": [[" << std::endl;
      continue;
    }
    Circles answer = circles::testing::mistaken_step(request.circles, {});
    const bool wrong = answer.size() >= 2 && mode != "extra-key" && !at_size;
    std::string line;
    if (wrong && token) {
      answer[0][0] = 0.5;  // a placeholder, replaced by the token below: the first number of "circles"
      line = format_line(kId, request.number, answer);
      line.replace(line.find("[[") + 2, 3, mode);
    } else {
      if (wrong) answer[0][0] = std::nextafter(answer[0][0], INFINITY);
      line = format_line(kId, request.number, answer);
      if (mode == "extra-key") line.insert(line.size() - 1, ",\"ms\":{\"parse\":[0.1,NaN],\"note\":\"}\"}");
    }
    fault_next = wrong && !token;
    std::cout << line << std::endl;
  }
  return 0;
}
