// Vulkan faults on demand, through DeviceContext's loader hook: every device function
// that returns a VkResult is wrapped, and the Nth such call made while a plan is armed
// fails with the plan's VkResult instead of reaching the driver.
//
// Out-of-memory faults are one call's: the call is not made, the ones after it are.
// A device loss is the device's: from the call that meets it on, submissions are not
// made and report VK_ERROR_DEVICE_LOST, and waits and query reads report it too (a wait
// still lets what was submitted before the loss finish, so nothing the validation layer
// tracks is left in flight).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <mutex>
#include <string>

#include "tidewater/render/device_context.hpp"

namespace tidewater::test {

enum class FaultKind {
    out_of_memory,  ///< the Nth call of any kind fails: odd N out of host memory, even N out of device memory
    device_lost,    ///< the Nth submission, wait or query read loses the device
};

class VulkanFaults {
  public:
    /// Counts the calls from now on and fails the `fail_at`-th (1-based; 0 counts only).
    void arm(FaultKind kind, int fail_at);
    /// Stops counting and failing; a lost device is found again.
    void disarm();
    /// The calls counted since arm() (for device_lost, the submissions, waits and reads).
    int calls() const;
    /// Whether the armed fault was met, with the function that met it and its VkResult.
    bool tripped() const;
    std::string tripped_in() const;
    VkResult fault() const;

    /// `ctx` with its loader hook set to this process's faulty functions.
    static render::DeviceContext hooked(render::DeviceContext ctx);

    // Called by the wrapped functions.
    enum class CallKind { other, submit, wait, read };
    /// The VkResult to return instead of calling the driver, or VK_SUCCESS to call it.
    VkResult on_call(const char* name, CallKind kind);
    bool device_is_lost() const;

  private:
    mutable std::mutex mutex_;
    bool armed_ = false;
    FaultKind kind_ = FaultKind::out_of_memory;
    int fail_at_ = 0;
    int calls_ = 0;
    bool tripped_ = false;
    bool lost_ = false;
    std::string tripped_in_;
    VkResult fault_ = VK_SUCCESS;
};

/// The one plan the hooked functions consult.
VulkanFaults& vulkan_faults();

}  // namespace tidewater::test
