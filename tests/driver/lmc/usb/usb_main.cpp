// The umockdev suites run under umockdev-wrapper (CTest sets it as the test launcher); run
// without it they skip with exit code 77, which CTest reports as skipped.
#include <gtest/gtest.h>

#include <cstdio>

#include "tests/driver/lmc/usb/umockdev_board.hpp"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  if (!::testing::GTEST_FLAG(list_tests) && !mark::lmc::test::UmockdevBoard::available()) {
    std::fprintf(stderr, "lmc_usb_tests: not running under umockdev-wrapper: skipped\n");
    return 77;
  }
  return RUN_ALL_TESTS();
}
