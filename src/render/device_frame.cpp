#include "render/device_frame.hpp"

#include <vector>

#include "device/transfer.hpp"

namespace clrt {

DeviceFrame::DeviceFrame(DeviceContext& device, const FrameData& frame,
                         std::shared_ptr<const GeometryData> tables)
    : host(frame),
      geometry(device, std::move(tables)),
      camera(upload(device, std::vector<dev::Camera>{frame.camera}, "camera")),
      params(upload(device, std::vector<dev::RenderParams>{frame.params}, "render parameters")),
      materials(upload(device, frame.materials, "material table")),
      bytes(geometry.tables().device_bytes() + sizeof(dev::Camera) + sizeof(dev::RenderParams) +
            sizeof(dev::Material) * frame.materials.size()) {
  const std::vector<unsigned char> table = light_table_bytes(frame, geometry.tables());
  lights = Global<const dev::Light>(device.allocate_copy(table.data(), table.size(), "light table"));
  bytes += table.size();
  // Neither table is ever empty (a buffer may not be): the texture table starts with its unread
  // row, the texels with the sRGB table.
  const TextureTable& t = *frame.textures;
  textures = upload(device, t.records, "texture table");
  texels = upload(device, t.texels, "texel table");
  bytes += sizeof(dev::Texture) * t.records.size() + sizeof(cl_uint) * t.texels.size();
}

void DeviceFrame::set_camera(DeviceContext& device, const dev::Camera& new_camera) {
  host.camera = new_camera;
  device.queue().enqueue_write_buffer(camera.buffer, 0, sizeof new_camera, &new_camera);
}

}  // namespace clrt
