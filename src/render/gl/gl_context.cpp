#include "render/gl/gl_context.hpp"

#include <array>
#include <cstdlib>
#include <stdexcept>

#include "render/components.hpp"
#include "render/gl/gl_backends.hpp"

namespace fl::render {
namespace {

constexpr std::array<std::string_view, 3> kNames = {"osmesa", "egl", "auto"};
// The order "auto" tries: EGL first, which finds a GPU where there is one (and llvmpipe where
// there is none), then OSMesa, which works everywhere but is software only.
constexpr std::array<GlBackend, 2> kAutoOrder = {GlBackend::kEgl, GlBackend::kOsmesa};

std::string valid_names() {
  std::string out;
  for (const std::string_view name : kNames) {
    if (!out.empty()) out += ", ";
    out += name;
  }
  return out;
}

std::unique_ptr<GlContext> make_backend(GlBackend backend, const GlContextOptions& options) {
  switch (backend) {
    case GlBackend::kOsmesa:
      return make_osmesa_context(options);
    case GlBackend::kEgl:
      return make_egl_context(options);
  }
  throw RenderError("unknown GL back end");
}

}  // namespace

void throw_without_osmesa(std::string_view what, std::string_view component) {
  std::string how = "GL back ends in this build: " + compiled_gl_backends() + "; configure with ";
  if (!kHasRender) how += "-DFRICTIONLAB_WITH_RENDER=ON ";
  how +=
      "-DFRICTIONLAB_WITH_OSMESA=ON after apt-get install libosmesa6-dev (or "
      "-DFRICTIONLAB_WITH_EGL=ON after apt-get install libegl-dev)";
  if (!kHasRender) how += " libpng-dev libstb-dev libgl-dev fonts-dejavu-core";
  throw_missing(what, component, how);
}

std::string_view gl_backend_name(GlBackend backend) {
  return backend == GlBackend::kOsmesa ? "osmesa" : "egl";
}

std::span<const std::string_view> gl_backend_names() {
  return kNames;
}

bool gl_backend_compiled(GlBackend backend) {
  switch (backend) {
    case GlBackend::kOsmesa:
      return kHasOsmesa;
    case GlBackend::kEgl:
      return kHasEgl;
  }
  return false;
}

std::string compiled_gl_backends() {
  std::string out;
  for (const GlBackend backend : kAutoOrder) {
    if (!gl_backend_compiled(backend)) continue;
    if (!out.empty()) out += ", ";
    out += gl_backend_name(backend);
  }
  return out.empty() ? "none" : out;
}

GlBackendRequest gl_backend_request(std::string_view requested) {
  if (!requested.empty()) return {std::string(requested), "--gl"};
  const char* env = std::getenv(kGlBackendVariable);
  if (env != nullptr && *env != '\0') return {env, kGlBackendVariable};
  return {"auto", "default"};
}

std::unique_ptr<GlContext> make_gl_context(const GlContextOptions& options, std::string* note) {
  if (note != nullptr) note->clear();
  GlBackendRequest request{options.backend, options.source};
  if (request.name.empty()) request = gl_backend_request();
  if (options.width <= 0 || options.height <= 0 || options.width > 16384 || options.height > 16384)
    throw RenderError("a frame of " + std::to_string(options.width) + "x" +
                      std::to_string(options.height) +
                      " pixels cannot be rendered; each side must be 1 to 16384");
  if (options.samples != 1 && options.samples != 4)
    throw RenderError("multisampling takes 1 or 4 samples, not " + std::to_string(options.samples));

  for (const GlBackend backend : kAutoOrder) {
    if (request.name == gl_backend_name(backend)) return make_backend(backend, options);
  }
  if (request.name == "auto") {
    std::string failures;
    std::string first_failure;
    for (const GlBackend backend : kAutoOrder) {
      if (!gl_backend_compiled(backend)) continue;
      try {
        auto context = make_backend(backend, options);
        // A back end that did not start before the one that did: say which and why, once.
        if (note != nullptr && !first_failure.empty())
          *note = first_failure + "; using " + std::string(gl_backend_name(backend));
        return context;
      } catch (const RenderError& e) {
        failures += "\n  " + std::string(gl_backend_name(backend)) + ": " + e.what();
        if (first_failure.empty())
          first_failure = "GL back end " + std::string(gl_backend_name(backend)) +
                          " did not start (" + e.what() + ")";
      }
    }
    // No back end compiled in: say so, never hand out a context that draws nothing.
    if (failures.empty()) throw_without_osmesa("rendering", "a GL back end (OSMesa)");
    throw RenderError("no GL back end could start:" + failures);
  }
  const std::string from =
      request.source.empty() ? std::string() : " (from " + request.source + ")";
  throw RenderError("unknown GL back end '" + request.name + "'" + from +
                    "; valid back ends: " + valid_names());
}

ImageView GlContext::read_frame() {
  if (queued_frames() != 0)
    throw std::logic_error("GlContext::read_frame with frames queued: take them first");
  queue_frame();
  return take_frame();
}

}  // namespace fl::render
