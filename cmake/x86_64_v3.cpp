// Exits 0 where this machine runs x86-64-v3 code, 1 where it does not (cmake/arch.cmake runs it at configure
// time). The bits are those of the x86-64 psABI's level 3, read from CPUID; XGETBV says whether the operating
// system saves the AVX registers, without which AVX instructions fault.
#include <cpuid.h>

#include <initializer_list>

namespace {
bool has(unsigned reg, int bit) { return (reg >> bit) & 1u; }
}  // namespace

int main() {
  unsigned a, b, c, d;
  if (!__get_cpuid(1, &a, &b, &c, &d)) return 1;
  // SSE3, SSSE3, FMA, CMPXCHG16B, SSE4.1, SSE4.2, MOVBE, POPCNT, XSAVE, OSXSAVE, AVX, F16C.
  for (int bit : {0, 9, 12, 13, 19, 20, 22, 23, 26, 27, 28, 29})
    if (!has(c, bit)) return 1;
  unsigned lo, hi;
  __asm__("xgetbv" : "=a"(lo), "=d"(hi) : "c"(0));
  if ((lo & 0x6u) != 0x6u) return 1;  // the XMM and YMM states
  if (!__get_cpuid_count(7, 0, &a, &b, &c, &d)) return 1;
  for (int bit : {3, 5, 8})  // BMI1, AVX2, BMI2
    if (!has(b, bit)) return 1;
  if (!__get_cpuid(0x80000001u, &a, &b, &c, &d)) return 1;
  for (int bit : {0, 5})  // LAHF-SAHF, LZCNT
    if (!has(c, bit)) return 1;
  return 0;
}
