#include "render/device_preparation.hpp"

#include "render/renderer_program.hpp"

namespace clrt {

DevicePreparation::DevicePreparation(const std::string& spec) {
  std::promise<std::vector<DeviceEntry>> choice;
  chosen_ = choice.get_future().share();
  built_ = std::async(std::launch::async, [spec, choice = std::move(choice)]() mutable {
    std::vector<DeviceEntry> entries;
    try {
      entries = select_devices(spec);
      choice.set_value(entries);
    } catch (...) {
      choice.set_exception(std::current_exception());
      throw;
    }
    std::vector<PreparedDevice> prepared;
    for (const DeviceEntry& entry : entries) {
      PreparedDevice d;
      d.context = std::make_unique<DeviceContext>(entry);
      d.program = build_renderer_program(*d.context);
      prepared.push_back(std::move(d));
    }
    return prepared;
  });
}

// A render that failed before taking the devices still waits for the thread, quietly.
DevicePreparation::~DevicePreparation() {
  if (built_.valid()) built_.wait();
}

const std::vector<DeviceEntry>& DevicePreparation::devices() { return chosen_.get(); }

std::vector<PreparedDevice> DevicePreparation::take() { return built_.get(); }

}  // namespace clrt
