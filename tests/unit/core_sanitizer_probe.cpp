// The sanitizer tree's flags (CMakeLists.txt, CREATURELAB_SANITIZE) catch what they are there for:
// each probe commits one kind of undefined behaviour and must stop the program with the report.
// Compiled into core_test in the sanitizer tree only (tests/unit/core.cmake).
#include <climits>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

namespace {

// Each reads its argument through a volatile copy, so the compiler cannot fold the undefined
// operation away before it runs.
int readPastTheEnd(int n) {
  std::vector<int> v(static_cast<std::size_t>(n), 1);
  volatile int* p = v.data();
  return p[n];
}

int readAfterFree() {
  auto owner = std::make_unique<int[]>(4);
  volatile int* p = owner.get();
  owner.reset();
  return p[1];
}

int readThrough(int* p) {
  volatile int* volatile q = p;
  return *q;
}

int addPastIntMax(int x) {
  volatile int a = x;
  return a + 1;
}
int shiftPastWidth(int x) {
  volatile int a = x;
  return 1 << a;
}
int divideBy(int x) {
  volatile int a = x;
  return 7 / a;
}

class SanitizerProbe : public ::testing::Test {
 protected:
  void SetUp() override { GTEST_FLAG_SET(death_test_style, "threadsafe"); }
};

TEST_F(SanitizerProbe, HeapOverflowStopsTheProgram) {
  EXPECT_DEATH(readPastTheEnd(4), "heap-buffer-overflow");
}

TEST_F(SanitizerProbe, UseAfterFreeStopsTheProgram) {
  EXPECT_DEATH(readAfterFree(), "heap-use-after-free");
}

TEST_F(SanitizerProbe, NullDereferenceStopsTheProgram) {
  EXPECT_DEATH(readThrough(nullptr), "SEGV on unknown address");
}

TEST_F(SanitizerProbe, SignedOverflowStopsTheProgram) {
  EXPECT_DEATH(addPastIntMax(INT_MAX), "signed integer overflow");
}

TEST_F(SanitizerProbe, OversizedShiftStopsTheProgram) {
  EXPECT_DEATH(shiftPastWidth(40), "shift exponent 40");
}

TEST_F(SanitizerProbe, IntegerDivisionByZeroStopsTheProgram) {
  EXPECT_DEATH(divideBy(0), "division by zero");
}

}  // namespace
