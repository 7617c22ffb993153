// The 3D view's keys, for whoever does not drag a mouse: the arrow keys move the camera around
// the rig, Shift with them slides it, + and − (or Page Up and Page Down) bring it nearer or take
// it away, Home puts it back where it started. World z is up; the camera looks at `target`.
import * as THREE from "three";

export type CameraMove =
  /** [rad] about the vertical through the target, and up or down */
  | { kind: "orbit"; around: number; up: number }
  /** fractions of the camera's distance, to its right and up */
  | { kind: "slide"; right: number; up: number }
  /** the distance times `factor` */
  | { kind: "zoom"; factor: number }
  | { kind: "home" };

const ORBIT_STEP = Math.PI / 36; // 5 degrees a press
const SLIDE_STEP = 0.05;
const ZOOM_STEP = 1.15;
/** [rad] the camera stays this far from straight above or below the target */
const POLE_MARGIN = Math.PI / 36;

/** The move a key asks for; null for a key the view leaves to the page. */
export function cameraMoveOf(event: KeyboardEvent): CameraMove | null {
  if (event.altKey || event.ctrlKey || event.metaKey) return null;
  const arrow: Record<string, [number, number]> = {
    ArrowLeft: [-1, 0],
    ArrowRight: [1, 0],
    ArrowUp: [0, 1],
    ArrowDown: [0, -1],
  };
  const along = arrow[event.key];
  if (along) {
    const [right, up] = along;
    return event.shiftKey
      ? { kind: "slide", right: right * SLIDE_STEP, up: up * SLIDE_STEP }
      : { kind: "orbit", around: right * ORBIT_STEP, up: up * ORBIT_STEP };
  }
  switch (event.key) {
    case "+":
    case "=":
    case "PageUp":
      return { kind: "zoom", factor: 1 / ZOOM_STEP };
    case "-":
    case "_":
    case "PageDown":
      return { kind: "zoom", factor: ZOOM_STEP };
    case "Home":
      return { kind: "home" };
  }
  return null;
}

/** Moves `camera` about `target` by `move` ("home" is the caller's), keeping its distance from
 * the target within `reach`; both are changed in place. */
export function moveCamera(
  camera: THREE.Camera,
  target: THREE.Vector3,
  move: CameraMove,
  reach: { min: number; max: number },
): void {
  const offset = camera.position.clone().sub(target);
  const distance = offset.length();
  if (move.kind === "orbit") {
    // Around the vertical: a positive turn takes the camera to its right.
    offset.applyAxisAngle(new THREE.Vector3(0, 0, 1), move.around);
    const elevation = Math.asin(THREE.MathUtils.clamp(offset.z / distance, -1, 1));
    const limit = Math.PI / 2 - POLE_MARGIN;
    const raised = THREE.MathUtils.clamp(elevation + move.up, -limit, limit);
    const level = Math.hypot(offset.x, offset.y);
    if (level > 0) {
      const scale = (distance * Math.cos(raised)) / level;
      offset.set(offset.x * scale, offset.y * scale, distance * Math.sin(raised));
    }
    camera.position.copy(target).add(offset);
  } else if (move.kind === "slide") {
    const forward = offset.clone().negate().normalize();
    const right = forward
      .clone()
      .cross(new THREE.Vector3(0, 0, 1))
      .normalize();
    const up = right.clone().cross(forward);
    const shift = right
      .multiplyScalar(move.right * distance)
      .add(up.multiplyScalar(move.up * distance));
    camera.position.add(shift);
    target.add(shift);
  } else if (move.kind === "zoom") {
    const wanted = THREE.MathUtils.clamp(distance * move.factor, reach.min, reach.max);
    camera.position.copy(target).add(offset.setLength(wanted));
  }
  camera.lookAt(target);
}
