#include "render/device_frame.hpp"

#include "device/transfer.hpp"

namespace clrt {

DeviceFrame::DeviceFrame(DeviceContext& device, const FrameData& frame,
                         std::shared_ptr<const GeometryData> tables)
    : host(frame),
      geometry(device, std::move(tables)),
      camera(upload(device, std::vector<dev::Camera>{frame.camera}, "camera")),
      params(upload(device, std::vector<dev::RenderParams>{frame.params}, "render parameters")),
      materials(upload(device, frame.materials, "material table")),
      lights(upload(device, frame.lights, "light table")),
      bytes(geometry.tables().device_bytes() + sizeof(dev::Camera) + sizeof(dev::RenderParams) +
            sizeof(dev::Material) * frame.materials.size() +
            sizeof(dev::Light) * frame.lights.size()) {}

void DeviceFrame::set_camera(DeviceContext& device, const dev::Camera& new_camera) {
  host.camera = new_camera;
  device.queue().enqueue_write_buffer(camera.buffer, 0, sizeof new_camera, &new_camera);
}

}  // namespace clrt
