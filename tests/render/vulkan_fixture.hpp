// A validated standalone device for render tests: any validation warning or
// error during a test fails it. The device is destroyed before the check, so
// Vulkan objects a test leaks (reported by the layer at vkDestroyDevice) fail it too.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "tidewater/render/standalone.hpp"

namespace tidewater::test {

class VulkanTest : public ::testing::Test {
  protected:
    void SetUp() override {
        render::StandaloneOptions options;
        options.validation = true;
        options.log = [this](const std::string& m) { messages_.push_back(m); };
        auto device = render::StandaloneDevice::create(options);
        ASSERT_TRUE(device.ok()) << device.error().message;
        device_ = std::move(device).value();
    }
    void TearDown() override {
        release();
        device_.reset();
        for (const auto& m : messages_) ADD_FAILURE() << m;
    }
    /// Destroy everything built on the device before the check (override in tests).
    virtual void release() {}
    const render::DeviceContext& context() const { return device_->context(); }
    std::unique_ptr<render::StandaloneDevice> device_;
    std::vector<std::string> messages_;
};

}  // namespace tidewater::test
