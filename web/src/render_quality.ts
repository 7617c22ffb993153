// How much the 3D view draws. A software WebGL (SwiftShader, llvmpipe) gets no antialiasing and,
// in place of the shadow map (whose extra pass every frame halves its frame rate), soft shadow
// blobs on the table under the plate and the rollers.

export interface RenderQuality {
  antialias: boolean;
  /** A directional light's shadow map, or soft blobs under the bodies. */
  shadows: "map" | "blobs";
  shadowMapSize: number;
}

const SOFTWARE = /swiftshader|llvmpipe|softpipe|software|microsoft basic render/i;

/** The renderer's name, asked of a throwaway context (unmasked where the browser masks it). */
function rendererName(): string {
  const canvas = document.createElement("canvas");
  const gl = canvas.getContext("webgl2") ?? canvas.getContext("webgl");
  if (!gl) return "";
  let name = String(gl.getParameter(gl.RENDERER) ?? "");
  if (/webkit webgl/i.test(name)) {
    const info = gl.getExtension("WEBGL_debug_renderer_info");
    if (info) name = String(gl.getParameter(info.UNMASKED_RENDERER_WEBGL) ?? name);
  }
  gl.getExtension("WEBGL_lose_context")?.loseContext();
  return name;
}

export function chooseRenderQuality(): RenderQuality {
  return SOFTWARE.test(rendererName())
    ? { antialias: false, shadows: "blobs", shadowMapSize: 0 }
    : { antialias: true, shadows: "map", shadowMapSize: 2048 };
}
