// What every integrator on one device reads, uploaded once per render: the scene's geometry and
// the frame's camera, constants, materials and lights.
#pragma once

#include "device/device_context.hpp"
#include "geometry/device_geometry.hpp"
#include "render/frame_setup.hpp"

namespace clrt {

struct DeviceFrame {
  DeviceFrame(DeviceContext& device, const FrameData& frame,
              std::shared_ptr<const GeometryData> tables);

  // Replaces the camera for the launches queued after this.
  void set_camera(DeviceContext& device, const dev::Camera& camera);

  FrameData host;  // the same records as on the device, for the host's own decisions
  DeviceGeometry geometry;
  Global<const dev::Camera> camera;
  Global<const dev::RenderParams> params;
  Global<const dev::Material> materials;
  Global<const dev::Texture> textures;
  Global<const cl_uint> texels;
  Global<const dev::Light> lights;
  std::uint64_t bytes = 0;  // on the device
};

}  // namespace clrt
