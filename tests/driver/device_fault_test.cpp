// fault_from: what a job reports for the exception a device threw.
#include <gtest/gtest.h>

#include "driver/device.hpp"

namespace mark {
namespace {

TEST(DeviceFault, FromTheExceptionADeviceThrew) {
  const DeviceFault own = fault_from(
      std::make_exception_ptr(DeviceFaultError({FaultCategory::out_of_field, "sample 7 outside", 7})), 99);
  EXPECT_EQ(own.category, FaultCategory::out_of_field);
  EXPECT_EQ(own.message, "sample 7 outside");
  EXPECT_EQ(own.at, 7u);
  const DeviceFault other = fault_from(std::make_exception_ptr(DeviceError("halted")), 42);
  EXPECT_EQ(other.category, FaultCategory::device);
  EXPECT_EQ(other.message, "halted");
  EXPECT_EQ(other.at, 42u);
  EXPECT_EQ(fault_from(std::make_exception_ptr(17), 3).message, "unknown device error");
}

}  // namespace
}  // namespace mark
