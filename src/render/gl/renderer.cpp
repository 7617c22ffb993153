#include "render/gl/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "render/components.hpp"
#include "render/gl/gl_api.hpp"
#include "render/gl/shader.hpp"

namespace fl::render {
namespace {

constexpr const char* kSceneVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_color;
uniform mat4 u_model;
uniform mat3 u_normal_matrix;
uniform mat4 u_view_projection;
uniform mat4 u_light_matrix;
uniform float u_normal_offset;
out vec3 v_world;
out vec3 v_normal;
out vec4 v_color;
out vec4 v_light_space;
void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  vec3 normal = normalize(u_normal_matrix * a_normal);
  v_world = world.xyz;
  v_normal = normal;
  // Colours come in sRGB and are lit in linear light. A part's colour is the same at its
  // vertices, so converting here rather than per fragment gives the same image for less work.
  v_color = vec4(pow(a_color.rgb, vec3(2.2)), a_color.a);
  // Looking the shadow up a little off the surface, along its normal, avoids shadow acne.
  v_light_space = u_light_matrix * vec4(world.xyz + normal * u_normal_offset, 1.0);
  gl_Position = u_view_projection * world;
}
)";

// Preceded by "#version 330 core" and "#define SOFT_SHADOWS 0 or 1".
constexpr const char* kSceneFragment = R"(
in vec3 v_world;
in vec3 v_normal;
in vec4 v_color;
in vec4 v_light_space;
uniform vec3 u_to_light;
uniform float u_light;
uniform float u_ambient;
uniform vec3 u_eye;
uniform int u_shadows;
uniform sampler2DShadow u_shadow_map;
uniform vec2 u_shadow_texel;
out vec4 frag;
float lit_fraction() {
  if (u_shadows == 0) return 1.0;
  vec3 p = v_light_space.xyz / v_light_space.w * 0.5 + 0.5;
  // Outside the map (beyond the shadow casters): lit, without the four lookups.
  if (p.z >= 1.0 || any(lessThan(p.xy, vec2(0.0))) || any(greaterThan(p.xy, vec2(1.0)))) return 1.0;
#if SOFT_SHADOWS
  // Four bilinear comparisons: a soft 3x3-texel edge, at the cost of four lookups.
  float sum = texture(u_shadow_map, vec3(p.xy + vec2(-0.75, -0.75) * u_shadow_texel, p.z));
  sum += texture(u_shadow_map, vec3(p.xy + vec2(0.75, -0.75) * u_shadow_texel, p.z));
  sum += texture(u_shadow_map, vec3(p.xy + vec2(-0.75, 0.75) * u_shadow_texel, p.z));
  sum += texture(u_shadow_map, vec3(p.xy + vec2(0.75, 0.75) * u_shadow_texel, p.z));
  return sum * 0.25;
#else
  // One bilinear comparison (2x2 texels).
  return texture(u_shadow_map, p);
#endif
}
void main() {
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  float n_dot_l = max(dot(n, u_to_light), 0.0);
  float lit = n_dot_l > 0.0 ? lit_fraction() : 0.0;
  // Lighting in linear light (v_color is linear already); the frame is written in sRGB.
  vec3 base = v_color.rgb;
  vec3 sky = vec3(0.80, 0.86, 1.00);
  vec3 ground = vec3(0.50, 0.45, 0.40);
  vec3 ambient = mix(ground, sky, n.z * 0.5 + 0.5) * u_ambient;
  vec3 h = normalize(u_to_light + normalize(u_eye - v_world));
  // (n.h)^48 = ((n.h)^16)^3 by squaring: six multiplications where pow costs a log and an exp,
  // which llvmpipe evaluates per fragment as polynomials (about 3 ms of a 720p frame).
  float h1 = max(dot(n, h), 0.0);
  float h2 = h1 * h1;
  float h4 = h2 * h2;
  float h8 = h4 * h4;
  float h16 = h8 * h8;
  float specular = h16 * h16 * h16 * 0.25 * lit * u_light;
  vec3 color = base * (ambient + u_light * n_dot_l * lit) + vec3(specular);
  frag = vec4(pow(clamp(color, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
}
)";

constexpr const char* kDepthVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_light_matrix;
uniform mat4 u_model;
void main() { gl_Position = u_light_matrix * u_model * vec4(a_position, 1.0); }
)";

constexpr const char* kDepthFragment = R"(#version 330 core
void main() {}
)";

constexpr const char* kOverlayVertex = R"(#version 330 core
layout(location = 0) in vec2 a_position;
layout(location = 1) in vec2 a_uv;
layout(location = 2) in vec4 a_color;
uniform vec2 u_frame;
out vec2 v_uv;
out vec4 v_color;
void main() {
  v_uv = a_uv;
  v_color = a_color;
  gl_Position = vec4(a_position.x / u_frame.x * 2.0 - 1.0, 1.0 - a_position.y / u_frame.y * 2.0,
                     0.0, 1.0);
}
)";

// Two programs rather than one with a branch on a uniform: llvmpipe samples the atlas for
// every fragment of a branching one, the panels' too.
constexpr const char* kOverlayShapeFragment = R"(#version 330 core
in vec2 v_uv;
in vec4 v_color;
out vec4 frag;
void main() { frag = v_color; }
)";

constexpr const char* kOverlayTextFragment = R"(#version 330 core
in vec2 v_uv;
in vec4 v_color;
uniform sampler2D u_atlas;
out vec4 frag;
void main() { frag = vec4(v_color.rgb, v_color.a * texture(u_atlas, v_uv).r); }
)";

struct Vertex {
  float position[3];
  float normal[3];
  std::uint8_t color[4];
};
static_assert(sizeof(Vertex) == 28);

std::uint8_t to_byte(float v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

// A pointer-sized offset into a bound buffer, as glVertexAttribPointer takes it.
const void* buffer_offset(std::size_t bytes) {
  return reinterpret_cast<const void*>(bytes);
}

}  // namespace

struct Renderer::Impl {
  struct GpuMesh {
    GLuint vao = 0;
    GLuint vertices = 0;
    GLuint indices = 0;
    GLsizei index_count = 0;
    Eigen::Vector3f centre = Eigen::Vector3f::Zero();
    float radius = 0.0f;
  };

  struct DrawItem {
    MeshId mesh;
    Eigen::Matrix4f model;
    bool casts_shadow;
  };

  Impl(GlContext& c, RendererOptions o)
      : context(c),
        gl(c.gl()),
        options(std::move(o)),
        scene(gl, "scene", kSceneVertex,
              std::string("#version 330 core\n#define SOFT_SHADOWS ") +
                  (options.soft_shadows ? "1" : "0") + kSceneFragment),
        depth(gl, "shadow depth", kDepthVertex, kDepthFragment),
        overlay_shapes(gl, "overlay shapes", kOverlayVertex, kOverlayShapeFragment),
        overlay_text(gl, "overlay text", kOverlayVertex, kOverlayTextFragment),
        overlay(options.font_path) {}

  GlContext& context;
  const GlApi& gl;
  RendererOptions options;
  ShaderProgram scene;
  ShaderProgram depth;
  ShaderProgram overlay_shapes;
  ShaderProgram overlay_text;
  Overlay overlay;

  std::vector<GpuMesh> meshes;
  std::vector<DrawItem> draws;
  Camera camera;
  DirectionalLight light;
  std::optional<ShadowBounds> fixed_bounds;
  FrameStats stats;
  bool in_frame = false;

  GLuint shadow_texture = 0;
  GLuint shadow_framebuffer = 0;
  GLuint overlay_vao = 0;
  GLuint overlay_buffer = 0;
  std::unordered_map<const Font*, GLuint> atlases;

  void create_shadow_map();
  void create_overlay_buffers();
  Eigen::Matrix4f light_matrix(const ShadowBounds& bounds) const;
  std::optional<ShadowBounds> caster_bounds() const;
  void shadow_pass(const Eigen::Matrix4f& light_matrix);
  void scene_pass(const Eigen::Matrix4f& light_matrix, float normal_offset, bool shadows);
  void overlay_pass();
  GLuint atlas_texture(const Font* font);
};

void Renderer::Impl::create_shadow_map() {
  const int size = options.shadow_map_size;
  gl.GenTextures(1, &shadow_texture);
  gl.BindTexture(GL_TEXTURE_2D, shadow_texture);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size, size, 0, GL_DEPTH_COMPONENT,
                GL_UNSIGNED_INT, nullptr);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  // Outside the map: lit.
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  gl.TexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  gl.GenFramebuffers(1, &shadow_framebuffer);
  gl.BindFramebuffer(GL_FRAMEBUFFER, shadow_framebuffer);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, shadow_texture, 0);
  gl.DrawBuffer(GL_NONE);
  gl.ReadBuffer(GL_NONE);
  const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw RenderError("the shadow map framebuffer is incomplete (status " + std::to_string(status) +
                      ")");
}

void Renderer::Impl::create_overlay_buffers() {
  gl.GenVertexArrays(1, &overlay_vao);
  gl.GenBuffers(1, &overlay_buffer);
  gl.BindVertexArray(overlay_vao);
  gl.BindBuffer(GL_ARRAY_BUFFER, overlay_buffer);
  constexpr auto stride = static_cast<GLsizei>(sizeof(OverlayVertex));
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride,
                         buffer_offset(offsetof(OverlayVertex, x)));
  gl.EnableVertexAttribArray(1);
  gl.VertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, stride,
                         buffer_offset(offsetof(OverlayVertex, u)));
  gl.EnableVertexAttribArray(2);
  gl.VertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride,
                         buffer_offset(offsetof(OverlayVertex, color)));
  gl.BindVertexArray(0);
}

std::optional<ShadowBounds> Renderer::Impl::caster_bounds() const {
  Eigen::AlignedBox3f box;
  for (const DrawItem& item : draws) {
    if (!item.casts_shadow) continue;
    const GpuMesh& mesh = meshes[item.mesh];
    const Eigen::Vector3f centre = (item.model * mesh.centre.homogeneous()).head<3>();
    // The largest axis scale of the model bounds the sphere's growth.
    const float scale = item.model.block<3, 3>(0, 0).colwise().norm().maxCoeff();
    const Eigen::Vector3f r = Eigen::Vector3f::Constant(mesh.radius * scale);
    box.extend(centre - r);
    box.extend(centre + r);
  }
  if (box.isEmpty()) return std::nullopt;
  return ShadowBounds{box.center(), box.diagonal().norm() / 2.0f};
}

Eigen::Matrix4f Renderer::Impl::light_matrix(const ShadowBounds& bounds) const {
  const Eigen::Vector3f d = light.direction.normalized();
  const float r = std::max(bounds.radius, 1e-3f);
  const Eigen::Vector3f up =
      std::abs(d.z()) > 0.99f ? Eigen::Vector3f::UnitY() : Eigen::Vector3f::UnitZ();
  Eigen::Matrix4f view = look_at(bounds.centre - d * (2.0f * r), bounds.centre, up);
  // Move the map in whole texels so that its edges do not crawl as the casters move.
  const float texel = 2.0f * r / static_cast<float>(options.shadow_map_size);
  const Eigen::Vector4f c = view * bounds.centre.homogeneous();
  view(0, 3) += std::round(c.x() / texel) * texel - c.x();
  view(1, 3) += std::round(c.y() / texel) * texel - c.y();
  return orthographic(-r, r, -r, r, 0.5f * r, 3.5f * r) * view;
}

void Renderer::Impl::shadow_pass(const Eigen::Matrix4f& light_m) {
  const int size = options.shadow_map_size;
  gl.BindFramebuffer(GL_FRAMEBUFFER, shadow_framebuffer);
  gl.Viewport(0, 0, size, size);
  gl.Clear(GL_DEPTH_BUFFER_BIT);
  gl.Enable(GL_DEPTH_TEST);
  gl.Disable(GL_CULL_FACE);
  gl.Enable(GL_POLYGON_OFFSET_FILL);
  gl.PolygonOffset(1.5f, 2.0f);
  depth.use();
  gl.UniformMatrix4fv(depth.uniform("u_light_matrix"), 1, GL_FALSE, light_m.data());
  const GLint model_location = depth.uniform("u_model");
  for (const DrawItem& item : draws) {
    if (!item.casts_shadow) continue;
    const GpuMesh& mesh = meshes[item.mesh];
    gl.UniformMatrix4fv(model_location, 1, GL_FALSE, item.model.data());
    gl.BindVertexArray(mesh.vao);
    gl.DrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr);
    stats.shadow_triangles += static_cast<std::size_t>(mesh.index_count) / 3;
  }
  gl.Disable(GL_POLYGON_OFFSET_FILL);
}

void Renderer::Impl::scene_pass(const Eigen::Matrix4f& light_m, float normal_offset, bool shadows) {
  const int width = context.width();
  const int height = context.height();
  gl.BindFramebuffer(GL_FRAMEBUFFER, context.frame_framebuffer());
  gl.Viewport(0, 0, width, height);
  const Color& bg = options.background;
  gl.ClearColor(bg.r, bg.g, bg.b, 1.0f);
  gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  gl.Enable(GL_CULL_FACE);
  gl.CullFace(GL_BACK);
  gl.Disable(GL_BLEND);

  scene.use();
  const Eigen::Matrix4f view_projection =
      projection_matrix(camera, width, height) * view_matrix(camera);
  gl.UniformMatrix4fv(scene.uniform("u_view_projection"), 1, GL_FALSE, view_projection.data());
  gl.UniformMatrix4fv(scene.uniform("u_light_matrix"), 1, GL_FALSE, light_m.data());
  gl.Uniform1f(scene.uniform("u_normal_offset"), normal_offset);
  const Eigen::Vector3f to_light = -light.direction.normalized();
  gl.Uniform3f(scene.uniform("u_to_light"), to_light.x(), to_light.y(), to_light.z());
  gl.Uniform1f(scene.uniform("u_light"), light.intensity);
  gl.Uniform1f(scene.uniform("u_ambient"), light.ambient);
  gl.Uniform3f(scene.uniform("u_eye"), camera.position.x(), camera.position.y(),
               camera.position.z());
  gl.Uniform1i(scene.uniform("u_shadows"), shadows ? 1 : 0);
  gl.Uniform1i(scene.uniform("u_shadow_map"), 0);
  const float texel = 1.0f / static_cast<float>(options.shadow_map_size);
  gl.Uniform2f(scene.uniform("u_shadow_texel"), texel, texel);
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindTexture(GL_TEXTURE_2D, shadow_texture);

  const GLint model_location = scene.uniform("u_model");
  const GLint normal_location = scene.uniform("u_normal_matrix");
  for (const DrawItem& item : draws) {
    const GpuMesh& mesh = meshes[item.mesh];
    const Eigen::Matrix3f normal_matrix = item.model.block<3, 3>(0, 0).inverse().transpose();
    gl.UniformMatrix4fv(model_location, 1, GL_FALSE, item.model.data());
    gl.UniformMatrix3fv(normal_location, 1, GL_FALSE, normal_matrix.data());
    gl.BindVertexArray(mesh.vao);
    gl.DrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr);
    stats.triangles += static_cast<std::size_t>(mesh.index_count) / 3;
  }
  stats.draws = draws.size();
}

GLuint Renderer::Impl::atlas_texture(const Font* font) {
  const auto found = atlases.find(font);
  if (found != atlases.end()) return found->second;
  const CoverageAtlas& atlas = font->atlas();
  GLuint texture = 0;
  gl.GenTextures(1, &texture);
  gl.BindTexture(GL_TEXTURE_2D, texture);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_R8, atlas.width, atlas.height, 0, GL_RED, GL_UNSIGNED_BYTE,
                atlas.coverage.data());
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  atlases.emplace(font, texture);
  return texture;
}

void Renderer::Impl::overlay_pass() {
  const auto& vertices = overlay.vertices();
  stats.overlay_vertices = vertices.size();
  if (vertices.empty()) return;
  gl.Disable(GL_DEPTH_TEST);
  gl.Disable(GL_CULL_FACE);
  gl.Enable(GL_BLEND);
  // Alpha stays 1 in the frame: colour blends, alpha accumulates toward opaque.
  gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  const auto frame_size = [&](const ShaderProgram& program) {
    program.use();
    gl.Uniform2f(program.uniform("u_frame"), static_cast<float>(context.width()),
                 static_cast<float>(context.height()));
  };
  frame_size(overlay_text);
  gl.Uniform1i(overlay_text.uniform("u_atlas"), 0);
  frame_size(overlay_shapes);
  const ShaderProgram* in_use = &overlay_shapes;
  gl.BindVertexArray(overlay_vao);
  gl.BindBuffer(GL_ARRAY_BUFFER, overlay_buffer);
  gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(OverlayVertex)),
                vertices.data(), GL_STREAM_DRAW);
  gl.ActiveTexture(GL_TEXTURE0);
  for (const OverlayBatch& batch : overlay.batches()) {
    if (batch.count == 0) continue;
    if (batch.font != nullptr) gl.BindTexture(GL_TEXTURE_2D, atlas_texture(batch.font));
    const ShaderProgram* wanted = batch.font != nullptr ? &overlay_text : &overlay_shapes;
    if (wanted != in_use) {
      wanted->use();
      in_use = wanted;
    }
    gl.DrawArrays(GL_TRIANGLES, static_cast<GLint>(batch.first), static_cast<GLsizei>(batch.count));
  }
  gl.Disable(GL_BLEND);
}

Renderer::Renderer(GlContext& context, RendererOptions options)
    : impl_(std::make_unique<Impl>(context, std::move(options))) {
  if (impl_->options.shadow_map_size < 16 || impl_->options.shadow_map_size > 8192)
    throw RenderError("a shadow map of " + std::to_string(impl_->options.shadow_map_size) +
                      " texels is out of range (16 to 8192)");
  impl_->create_shadow_map();
  impl_->create_overlay_buffers();
  impl_->gl.check("creating the renderer");
}

Renderer::~Renderer() {
  Impl& r = *impl_;
  const GlApi& gl = r.gl;
  for (Impl::GpuMesh& mesh : r.meshes) {
    gl.DeleteVertexArrays(1, &mesh.vao);
    gl.DeleteBuffers(1, &mesh.vertices);
    gl.DeleteBuffers(1, &mesh.indices);
  }
  for (auto& [font, texture] : r.atlases) gl.DeleteTextures(1, &texture);
  gl.DeleteVertexArrays(1, &r.overlay_vao);
  gl.DeleteBuffers(1, &r.overlay_buffer);
  gl.DeleteFramebuffers(1, &r.shadow_framebuffer);
  gl.DeleteTextures(1, &r.shadow_texture);
}

MeshId Renderer::upload(const MeshData& data) {
  data.validate();
  Impl& r = *impl_;
  const GlApi& gl = r.gl;
  std::vector<Vertex> vertices(data.positions.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    Vertex& v = vertices[i];
    std::memcpy(v.position, data.positions[i].data(), sizeof v.position);
    std::memcpy(v.normal, data.normals[i].data(), sizeof v.normal);
    const Color& c = data.colors[i];
    v.color[0] = to_byte(c.r);
    v.color[1] = to_byte(c.g);
    v.color[2] = to_byte(c.b);
    v.color[3] = to_byte(c.a);
  }
  Impl::GpuMesh mesh;
  std::tie(mesh.centre, mesh.radius) = data.bounding_sphere();
  mesh.index_count = static_cast<GLsizei>(data.indices.size());
  gl.GenVertexArrays(1, &mesh.vao);
  gl.BindVertexArray(mesh.vao);
  gl.GenBuffers(1, &mesh.vertices);
  gl.BindBuffer(GL_ARRAY_BUFFER, mesh.vertices);
  gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
                vertices.data(), GL_STATIC_DRAW);
  gl.GenBuffers(1, &mesh.indices);
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh.indices);
  gl.BufferData(GL_ELEMENT_ARRAY_BUFFER,
                static_cast<GLsizeiptr>(data.indices.size() * sizeof(std::uint32_t)),
                data.indices.data(), GL_STATIC_DRAW);
  constexpr auto stride = static_cast<GLsizei>(sizeof(Vertex));
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride,
                         buffer_offset(offsetof(Vertex, position)));
  gl.EnableVertexAttribArray(1);
  gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, buffer_offset(offsetof(Vertex, normal)));
  gl.EnableVertexAttribArray(2);
  gl.VertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride,
                         buffer_offset(offsetof(Vertex, color)));
  gl.BindVertexArray(0);
  gl.check("uploading a mesh");
  r.meshes.push_back(mesh);
  return static_cast<MeshId>(r.meshes.size() - 1);
}

void Renderer::begin_frame(const Camera& camera, const DirectionalLight& light) {
  Impl& r = *impl_;
  r.camera = camera;
  r.light = light;
  r.draws.clear();
  r.overlay.clear();
  r.stats = FrameStats{};
  r.in_frame = true;
}

void Renderer::draw(MeshId mesh, const Eigen::Affine3f& model, bool casts_shadow) {
  Impl& r = *impl_;
  if (!r.in_frame) throw std::logic_error("Renderer::draw outside begin_frame/end_frame");
  if (mesh >= r.meshes.size())
    throw std::invalid_argument("Renderer::draw: no mesh with id " + std::to_string(mesh));
  r.draws.push_back(Impl::DrawItem{mesh, model.matrix(), casts_shadow});
}

void Renderer::set_shadow_bounds(std::optional<ShadowBounds> bounds) {
  impl_->fixed_bounds = bounds;
}

Overlay& Renderer::overlay() {
  return impl_->overlay;
}

ImageView Renderer::end_frame() {
  if (impl_->context.queued_frames() != 0)
    throw std::logic_error("Renderer::end_frame with frames queued: take them first");
  submit_frame();
  return impl_->context.take_frame();
}

void Renderer::submit_frame() {
  Impl& r = *impl_;
  if (!r.in_frame) throw std::logic_error("Renderer::submit_frame without begin_frame");
  r.in_frame = false;
  const std::optional<ShadowBounds> bounds = r.fixed_bounds ? r.fixed_bounds : r.caster_bounds();
  const bool shadows = r.options.shadows && bounds.has_value();
  Eigen::Matrix4f light_m = Eigen::Matrix4f::Identity();
  float normal_offset = 0.0f;
  if (shadows) {
    light_m = r.light_matrix(*bounds);
    // One and a half shadow texels, in metres.
    normal_offset = 3.0f * bounds->radius / static_cast<float>(r.options.shadow_map_size);
    r.shadow_pass(light_m);
  }
  r.scene_pass(light_m, normal_offset, shadows);
  r.overlay_pass();
  r.gl.BindVertexArray(0);
  r.gl.check("drawing the frame");
  r.context.queue_frame();
}

const FrameStats& Renderer::last_frame_stats() const {
  return impl_->stats;
}

GlContext& Renderer::context() {
  return impl_->context;
}

}  // namespace fl::render
