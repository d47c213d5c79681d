// The example application's frame: everything Vulkan is its own (instance, device, buffers,
// images, render pass, pipelines, descriptor sets, command buffers); confvis supplies the map
// upload, the per-wall bounds and the conformal pre-pass (confvis/backends/vulkan/byo_*.hpp).
#include "app_renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <optional>
#include <vector>

#include <glm/gtc/packing.hpp>

#include "app_device.hpp"
#include "app_pipelines.hpp"
#include "confvis/backends/vulkan/byo_descriptors.hpp"
#include "confvis/backends/vulkan/byo_frame.hpp"
#include "confvis/backends/vulkan/byo_prepass.hpp"
#include "confvis/backends/vulkan/byo_upload.hpp"
#include "confvis/backends/vulkan/warp_interface.hpp"
#include "confvis/base/error.hpp"
#include "confvis/engine/viewer.hpp"

namespace byo_example {
namespace cv = confvis::vulkan;
namespace {

// The application's own vertices: attributes in an order, formats and stride of its choosing
// (AppOptions::VertexFormat), described to the pre-pass by a VertexLayout, and a tag per vertex
// that only the application uses.
struct AppGeometry {
  std::vector<unsigned char> vertices;
  std::size_t vertexCount = 0;
  cv::VertexLayout layout;
  std::vector<std::uint32_t> indices;
  std::vector<cv::PrepassMesh> meshes;
  std::vector<const confvis::Mesh*> sources;  // per entry of `meshes`
};

cv::VertexLayout layoutFor(AppOptions::VertexFormat format) {
  cv::VertexLayout l;
  switch (format) {
    case AppOptions::VertexFormat::Float32:
      l = {36, 8, VK_FORMAT_R32G32B32_SFLOAT, 20, VK_FORMAT_R32G32B32_SFLOAT, 0,
           VK_FORMAT_R32G32_SFLOAT};
      break;
    case AppOptions::VertexFormat::Half:
      l = {24, 0, VK_FORMAT_R16G16B16A16_SFLOAT, 8, VK_FORMAT_R16G16B16A16_SFLOAT, 16,
           VK_FORMAT_R16G16_SFLOAT};
      break;
    case AppOptions::VertexFormat::Mixed:
      l = {32, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 16, VK_FORMAT_R16G16B16A16_SFLOAT, 24,
           VK_FORMAT_R16G16_UNORM};
      break;
  }
  return l;
}

// Writes `values` at `at` in `format` (one of layoutFor's).
void pack(unsigned char* at, VkFormat format, glm::vec4 values) {
  const auto put = [&](const auto& array) { std::memcpy(at, array.data(), sizeof(array)); };
  const auto half = [](float f) { return glm::packHalf1x16(f); };
  switch (format) {
    case VK_FORMAT_R32G32_SFLOAT: put(std::array<float, 2>{values.x, values.y}); break;
    case VK_FORMAT_R32G32B32_SFLOAT: put(std::array<float, 3>{values.x, values.y, values.z}); break;
    case VK_FORMAT_R32G32B32A32_SFLOAT:
      put(std::array<float, 4>{values.x, values.y, values.z, values.w});
      break;
    case VK_FORMAT_R16G16_SFLOAT: put(std::array<std::uint16_t, 2>{half(values.x), half(values.y)}); break;
    case VK_FORMAT_R16G16B16A16_SFLOAT:
      put(std::array<std::uint16_t, 4>{half(values.x), half(values.y), half(values.z),
                                       half(values.w)});
      break;
    case VK_FORMAT_R16G16_UNORM:
      put(std::array<std::uint16_t, 2>{glm::packUnorm1x16(values.x), glm::packUnorm1x16(values.y)});
      break;
    default: throw confvis::Error(confvis::ErrorCode::Internal, "example: unpacked vertex format");
  }
}

AppGeometry flatten(const confvis::Scene& scene, AppOptions::VertexFormat format) {
  AppGeometry g;
  g.layout = layoutFor(format);
  const std::uint32_t stride = g.layout.stride;
  for (const confvis::Mesh& mesh : scene.meshes) {
    if (mesh.triangles.empty()) continue;
    cv::PrepassMesh range;
    range.firstIndex = static_cast<std::uint32_t>(g.indices.size());
    range.indexCount = static_cast<std::uint32_t>(3 * mesh.triangles.size());
    range.vertexOffset = static_cast<std::int32_t>(g.vertexCount);
    g.vertices.resize((g.vertexCount + mesh.positions.size()) * stride);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i, ++g.vertexCount) {
      unsigned char* v = g.vertices.data() + g.vertexCount * stride;
      const glm::vec3 n = mesh.normals.empty() ? glm::vec3(0.0f) : mesh.normals[i];
      const glm::vec2 uv = mesh.uvs.empty() ? glm::vec2(0.0f) : mesh.uvs[i];
      pack(v + g.layout.positionOffset, g.layout.positionFormat, glm::vec4(mesh.positions[i], 1.0f));
      pack(v + g.layout.normalOffset, g.layout.normalFormat, glm::vec4(n, 0.0f));
      pack(v + g.layout.uvOffset, g.layout.uvFormat, glm::vec4(uv, 0.0f, 0.0f));
      const auto tag = static_cast<std::uint32_t>(g.meshes.size());
      std::memcpy(v + stride - sizeof(tag), &tag, sizeof(tag));
    }
    for (const glm::uvec3& t : mesh.triangles) g.indices.insert(g.indices.end(), {t.x, t.y, t.z});
    g.meshes.push_back(range);
    g.sources.push_back(&mesh);
  }
  return g;
}

// A buffer or image with its memory, owned by the application.
struct AppBuffer {
  VkDevice device = VK_NULL_HANDLE;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;
  AppBuffer(const AppVulkan& vk, VkDeviceSize size, VkBufferUsageFlags usage) : device(vk.device()) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    vkCheck(vkCreateBuffer(device, &info, nullptr, &buffer), "vkCreateBuffer");
    VkMemoryRequirements needs;
    vkGetBufferMemoryRequirements(device, buffer, &needs);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = needs.size;
    alloc.memoryTypeIndex = vk.memoryType(
        needs.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    vkCheck(vkAllocateMemory(device, &alloc, nullptr, &memory), "vkAllocateMemory");
    vkCheck(vkBindBufferMemory(device, buffer, memory, 0), "vkBindBufferMemory");
    vkCheck(vkMapMemory(device, memory, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
  }
  ~AppBuffer() {
    vkDestroyBuffer(device, buffer, nullptr);
    vkFreeMemory(device, memory, nullptr);
  }
  AppBuffer(const AppBuffer&) = delete;
  AppBuffer& operator=(const AppBuffer&) = delete;
};

struct AppTarget {
  VkDevice device = VK_NULL_HANDLE;
  VkImage images[2] = {};
  VkDeviceMemory memory[2] = {};
  VkImageView views[2] = {};
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  AppTarget(const AppVulkan& vk, VkRenderPass renderPass, std::uint32_t width,
            std::uint32_t height)
      : device(vk.device()) {
    const VkFormat formats[2] = {kAppColorFormat, kAppDepthFormat};
    const VkImageUsageFlags usages[2] = {
        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT};
    const VkImageAspectFlags aspects[2] = {VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_ASPECT_DEPTH_BIT};
    for (int i = 0; i < 2; ++i) {
      VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
      info.imageType = VK_IMAGE_TYPE_2D;
      info.format = formats[i];
      info.extent = {width, height, 1};
      info.mipLevels = 1;
      info.arrayLayers = 1;
      info.samples = VK_SAMPLE_COUNT_1_BIT;
      info.tiling = VK_IMAGE_TILING_OPTIMAL;
      info.usage = usages[i];
      vkCheck(vkCreateImage(device, &info, nullptr, &images[i]), "vkCreateImage");
      VkMemoryRequirements needs;
      vkGetImageMemoryRequirements(device, images[i], &needs);
      VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
      alloc.allocationSize = needs.size;
      alloc.memoryTypeIndex =
          vk.memoryType(needs.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
      vkCheck(vkAllocateMemory(device, &alloc, nullptr, &memory[i]), "vkAllocateMemory");
      vkCheck(vkBindImageMemory(device, images[i], memory[i], 0), "vkBindImageMemory");
      VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
      viewInfo.image = images[i];
      viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
      viewInfo.format = formats[i];
      viewInfo.subresourceRange = {aspects[i], 0, 1, 0, 1};
      vkCheck(vkCreateImageView(device, &viewInfo, nullptr, &views[i]), "vkCreateImageView");
    }
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = renderPass;
    info.attachmentCount = 2;
    info.pAttachments = views;
    info.width = width;
    info.height = height;
    info.layers = 1;
    vkCheck(vkCreateFramebuffer(device, &info, nullptr, &framebuffer), "vkCreateFramebuffer");
  }
  ~AppTarget() {
    vkDestroyFramebuffer(device, framebuffer, nullptr);
    for (int i = 0; i < 2; ++i) {
      vkDestroyImageView(device, views[i], nullptr);
      vkDestroyImage(device, images[i], nullptr);
      vkFreeMemory(device, memory[i], nullptr);
    }
  }
  AppTarget(const AppTarget&) = delete;
  AppTarget& operator=(const AppTarget&) = delete;
};

void writeBuffer(VkDevice device, VkDescriptorSet set, std::uint32_t binding,
                 VkDescriptorType type, VkBuffer buffer) {
  VkDescriptorBufferInfo info{buffer, 0, VK_WHOLE_SIZE};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = type;
  write.pBufferInfo = &info;
  vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
}

void writeImage(VkDevice device, VkDescriptorSet set, std::uint32_t binding, VkSampler sampler,
                VkImageView view) {
  VkDescriptorImageInfo info{sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  write.pImageInfo = &info;
  vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
}

// Frees the application's descriptor pool and samplers on every way out.
struct AppObjects {
  VkDevice device;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkSampler textureSampler = VK_NULL_HANDLE;
  ~AppObjects() {
    if (pool) vkDestroyDescriptorPool(device, pool, nullptr);
    if (textureSampler) vkDestroySampler(device, textureSampler, nullptr);
  }
};

}  // namespace

std::vector<confvis::WallImage> renderThroughMap(const confvis::DisplayConfig& config,
                                                 const confvis::Scene& scene,
                                                 const confvis::RetargetMap& map,
                                                 const AppOptions& options) {
  AppVulkan vk(options.device, options.validation, options.onValidationMessage);
  const VkDevice device = vk.device();
  const cv::AppDevice app = vk.appDevice();

  // The application's geometry in its own vertex and index buffers (host-visible here, written
  // by the host before any submission: an application's staged upload would do as well),
  // described to the pre-pass by its layout; the half-float layout takes 16-bit indices.
  const AppGeometry geometry = flatten(scene, options.vertexFormat);
  const bool shortIndices = options.vertexFormat == AppOptions::VertexFormat::Half &&
                            std::all_of(geometry.indices.begin(), geometry.indices.end(),
                                        [](std::uint32_t i) { return i <= 0xffff; });
  const std::size_t indexSize = shortIndices ? 2 : 4;
  AppBuffer vertexBuffer(vk, geometry.vertices.size(),
                         VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  std::memcpy(vertexBuffer.mapped, geometry.vertices.data(), geometry.vertices.size());
  AppBuffer indexBuffer(vk, geometry.indices.size() * indexSize,
                        VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  for (std::size_t i = 0; i < geometry.indices.size(); ++i) {
    const std::uint16_t shortIndex = static_cast<std::uint16_t>(geometry.indices[i]);
    std::memcpy(static_cast<unsigned char*>(indexBuffer.mapped) + i * indexSize,
                shortIndices ? static_cast<const void*>(&shortIndex) : &geometry.indices[i],
                indexSize);
  }
  cv::PrepassBuffers buffers;
  buffers.vertexBuffer = vertexBuffer.buffer;
  buffers.vertexCount = geometry.vertexCount;
  buffers.layout = geometry.layout;
  if (options.wrongPositionOffset) buffers.layout.positionOffset = geometry.layout.normalOffset;
  buffers.indexBuffer = indexBuffer.buffer;
  buffers.indexCount = static_cast<std::uint32_t>(geometry.indices.size());
  buffers.indexType = shortIndices ? VK_INDEX_TYPE_UINT16 : VK_INDEX_TYPE_UINT32;
  buffers.meshes = geometry.meshes;
  cv::ConformalPrepassStep prepass(app, buffers);
  // The map: uploaded now (its own submission), or recorded with the frame's pre-pass below.
  std::optional<cv::UploadedRetargetMap> uploadedMap;
  if (!options.recordedUpload) uploadedMap.emplace(cv::uploadRetargetMap(app, map));

  // Textures: the scene's and a white one for meshes without.
  std::vector<cv::UploadedTexture> textures;
  for (const confvis::Texture& texture : scene.textures)
    textures.push_back(cv::uploadTexture(app, texture));
  confvis::Texture white;
  white.width = white.height = 1;
  white.rgba = {1.0f, 1.0f, 1.0f, 1.0f};
  textures.push_back(cv::uploadTexture(app, white));

  AppPipelines pipelines(device);
  AppObjects objects{device};
  VkSamplerCreateInfo samplerInfo{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  samplerInfo.magFilter = samplerInfo.minFilter = VK_FILTER_LINEAR;
  samplerInfo.addressModeU = samplerInfo.addressModeV = samplerInfo.addressModeW =
      VK_SAMPLER_ADDRESS_MODE_REPEAT;
  vkCheck(vkCreateSampler(device, &samplerInfo, nullptr, &objects.textureSampler),
          "vkCreateSampler");
  const auto materials = static_cast<std::uint32_t>(textures.size());
  const std::array<VkDescriptorPoolSize, 3> sizes = {{
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
      {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 5},
      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, cv::kWarpSetImageSamplers + materials},
  }};
  std::vector<VkDescriptorSetLayout> layouts = {pipelines.frameSetLayout(),
                                                pipelines.warpSetLayout()};
  layouts.resize(2 + materials, pipelines.materialSetLayout());
  objects.pool = cv::makeDescriptorPool(device, sizes, static_cast<std::uint32_t>(layouts.size()));
  const std::vector<VkDescriptorSet> sets = cv::allocateDescriptorSets(device, objects.pool, layouts);
  const VkDescriptorSet frameSet = sets[0], warpSet = sets[1];
  for (std::uint32_t m = 0; m < materials; ++m)
    writeImage(device, sets[2 + m], 0, objects.textureSampler, textures[m].view());

  // The frame: navigation at rest, the centre eye, one view per wall with its warp bounds.
  const confvis::VirtualCamera camera;
  const glm::dvec3 eye = confvis::eyePosition(confvis::HeadPose{}, confvis::Eye::Center,
                                              config.eyeSeparation);
  cv::PrepassFrame frame;
  frame.worldToPhysical = cv::worldToPhysical(config, camera);
  frame.tolerances.errorPixels = options.errorPixels;
  std::vector<AppView> views;
  for (const confvis::Wall& wall : config.walls) {
    const auto scaled = [&](int pixels) {
      return static_cast<std::uint32_t>(std::max(1.0, std::round(pixels * options.resolutionScale)));
    };
    const cv::PrepassWall target{&wall, scaled(wall.width), scaled(wall.height)};
    frame.walls.push_back(target);
    const cv::WallWarpBounds bounds =
        cv::wallWarpBounds(wall, target.width, target.height, map.reference, frame.tolerances);
    views.push_back({glm::mat4(cv::wallViewProjection(wall, eye)),
                     glm::vec4(glm::vec3(cv::headlightPosition(eye, config, &map, camera)), 1.0f),
                     glm::vec4(float(bounds.errorAngle), float(bounds.maxSegmentAngle),
                               float(bounds.cutGapAngle), 1.0f)});
  }
  AppBuffer frameBuffer(vk, sizeof(AppFrame), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  const AppFrame frameUniforms{glm::mat4(frame.worldToPhysical),
                               glm::vec4(glm::vec3(map.reference), 1.0f)};
  std::memcpy(frameBuffer.mapped, &frameUniforms, sizeof(frameUniforms));
  AppBuffer viewBuffer(vk, views.size() * sizeof(AppView), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  std::memcpy(viewBuffer.mapped, views.data(), views.size() * sizeof(AppView));

  // The conformal pre-pass on the application's own command buffer; the host then knows the
  // tessellated lists' sizes.
  cv::UploadStaging staging;
  vk.submitAndWait([&](VkCommandBuffer cmd) {
    if (options.recordedUpload) {
      cv::RecordedRetargetMapUpload recorded = cv::recordRetargetMapUpload(app, cmd, map);
      uploadedMap.emplace(std::move(recorded.map));
      staging = std::move(recorded.staging);
    }
    prepass.record(cmd, *uploadedMap, frame);
  });
  staging.submissionCompleted();  // submitAndWait waited for it
  const cv::UploadedRetargetMap& warpMap = *uploadedMap;

  writeBuffer(device, frameSet, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, frameBuffer.buffer);
  writeBuffer(device, frameSet, 1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, viewBuffer.buffer);
  writeBuffer(device, frameSet, 2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, prepass.patchLevels());
  writeBuffer(device, frameSet, 3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, prepass.tessellatedIndices());
  writeBuffer(device, frameSet, 4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, prepass.vertexBuffer());
  writeBuffer(device, frameSet, 5, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, prepass.warpBuffer());
  cv::writeWarpSet(device, warpSet, warpMap);

  std::vector<confvis::WallImage> images;
  for (std::size_t w = 0; w < frame.walls.size(); ++w) {
    const std::uint32_t width = frame.walls[w].width, height = frame.walls[w].height;
    AppTarget target(vk, pipelines.renderPass(), width, height);
    AppBuffer readback(vk, VkDeviceSize{width} * height * 4 * sizeof(float),
                       VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    vk.submitAndWait([&](VkCommandBuffer cmd) {
      std::array<VkClearValue, 2> clear{};
      clear[0].color = {{0.0f, 0.0f, 0.0f, 0.0f}};
      clear[1].depthStencil = {0.0f, 0};  // reverse-Z: 0 is infinitely far
      VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
      begin.renderPass = pipelines.renderPass();
      begin.framebuffer = target.framebuffer;
      begin.renderArea = {{0, 0}, {width, height}};
      begin.clearValueCount = 2;
      begin.pClearValues = clear.data();
      vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
      const VkViewport viewport{0.0f, 0.0f, float(width), float(height), 0.0f, 1.0f};
      const VkRect2D scissor{{0, 0}, {width, height}};
      vkCmdSetViewport(cmd, 0, 1, &viewport);
      vkCmdSetScissor(cmd, 0, 1, &scissor);
      const VkPipelineLayout layout = pipelines.layout();
      const std::array<VkDescriptorSet, 2> frameSets = {frameSet, warpSet};
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 2,
                              frameSets.data(), 0, nullptr);
      const std::array<VkBuffer, 2> vertexBuffers = {prepass.vertexBuffer(), prepass.warpBuffer()};
      const std::array<VkDeviceSize, 2> offsets = {0, 0};
      vkCmdBindVertexBuffers(cmd, 0, 2, vertexBuffers.data(), offsets.data());
      // Per list, per mesh: the mesh's material and push constants, then its draw.
      const auto drawList = [&](VkPipeline pipeline, cv::DrawList list) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
        if (list == cv::DrawList::Flat || list == cv::DrawList::Pieces)
          vkCmdBindIndexBuffer(cmd,
                               list == cv::DrawList::Flat ? prepass.flatIndices()
                                                          : prepass.pieceIndices(),
                               0, VK_INDEX_TYPE_UINT32);
        for (std::size_t m = 0; m < prepass.meshCount(); ++m) {
          const confvis::Mesh& mesh = *geometry.sources[m];
          glm::vec4 color(1.0f);
          std::uint32_t material = materials - 1;  // white
          if (mesh.material >= 0) {
            const confvis::Material& source = scene.materials[std::size_t(mesh.material)];
            color = source.baseColorFactor;
            if (source.baseColorTexture >= 0 && !mesh.uvs.empty())
              material = static_cast<std::uint32_t>(source.baseColorTexture);
          }
          vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 2, 1,
                                  &sets[2 + material], 0, nullptr);
          AppPush push{color, static_cast<std::uint32_t>(w), mesh.normals.empty() ? 0u : 1u, 0};
          if (list == cv::DrawList::Flat || list == cv::DrawList::Pieces) {
            vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof(push), &push);
            vkCmdDrawIndexedIndirect(cmd, prepass.drawCommandBuffer(),
                                     cv::ConformalPrepassStep::drawCommandOffset(m, list), 1,
                                     sizeof(VkDrawIndexedIndirectCommand));
          } else {  // no index buffer: warp.vert reads the list (byo_prepass.hpp)
            const VkDrawIndexedIndirectCommand c = prepass.drawCommand(m, list);
            push.vertexOffset = c.vertexOffset;
            vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof(push), &push);
            if (c.indexCount > 0) vkCmdDraw(cmd, c.indexCount, 1, c.firstIndex, 0);
          }
        }
      };
      drawList(pipelines.flat(), cv::DrawList::Flat);
      if (!options.onlyFlatList) {
        drawList(pipelines.flat(), cv::DrawList::Pieces);
        drawList(pipelines.tessellated(), cv::DrawList::Tessellated);
        drawList(pipelines.dropping(), cv::DrawList::Dropping);
      }
      vkCmdEndRenderPass(cmd);
      VkBufferImageCopy region{};
      region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      region.imageExtent = {width, height, 1};
      vkCmdCopyImageToBuffer(cmd, target.images[0], VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                             readback.buffer, 1, &region);
      VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
      toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
      toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                           &toHost, 0, nullptr, 0, nullptr);
    });
    confvis::ImageRGBA image(static_cast<int>(width), static_cast<int>(height));
    std::memcpy(image.pixels.data(), readback.mapped, image.pixels.size() * sizeof(float));
    images.push_back({config.walls[w].name, confvis::Eye::Center, std::move(image)});
  }
  return images;
}

}  // namespace byo_example
