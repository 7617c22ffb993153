// The rig in 3D: world z up, x along the plate's motion; orbit and zoom with the mouse, a finger
// or the keys (camera_keys.ts). It draws a frame only when something changed: a new pose of the
// plate, a camera move, a resize; a paused run's repeated states draw nothing.
import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";
import { cameraMoveOf, moveCamera } from "./camera_keys";
import type { LabState, Rig } from "./lab_types";
import { ForceArrows } from "./force_arrows";
import { t } from "./i18n";
import { chooseRenderQuality, type RenderQuality } from "./render_quality";
import { buildRig, type RigModel } from "./rig_model";

export class RigView {
  private readonly renderer: THREE.WebGLRenderer;
  private readonly scene = new THREE.Scene();
  private readonly camera = new THREE.PerspectiveCamera(35, 16 / 9, 0.005, 20);
  private readonly controls: OrbitControls;
  private readonly sun = new THREE.DirectionalLight(0xffffff, 2.2);
  private model: RigModel | null = null;
  private arrows: ForceArrows | null = null;
  private frame = 0;
  private frames = 0;
  /** What the last state posed: the plate, the rollers and the forces drawn. */
  private pose: number[] = [];
  /** Where setRig put the camera, for "Reset view" and Home. */
  private readonly home = { position: new THREE.Vector3(), target: new THREE.Vector3() };
  private nearSideShown = false;
  private readonly resize: ResizeObserver;
  private readonly quality: RenderQuality = chooseRenderQuality();

  constructor(private readonly container: HTMLElement) {
    this.renderer = new THREE.WebGLRenderer({
      antialias: this.quality.antialias,
      preserveDrawingBuffer: true,
    });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    this.renderer.shadowMap.enabled = this.quality.shadows === "map";
    this.renderer.shadowMap.type = THREE.PCFShadowMap;
    const canvas = this.renderer.domElement;
    canvas.setAttribute("role", "img");
    canvas.setAttribute("aria-label", t("view-canvas-label"));
    // index.html's words: the set-up in a sentence (rig_description.ts) and the view's keys.
    canvas.setAttribute("aria-describedby", "rig-setup view-keys");
    canvas.tabIndex = 0;
    container.append(canvas);

    this.scene.background = new THREE.Color(0xeef1f4);
    this.camera.up.set(0, 0, 1);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x8a8578, 1.3));
    this.sun.castShadow = this.quality.shadows === "map";
    if (this.sun.castShadow) {
      this.sun.shadow.mapSize.set(this.quality.shadowMapSize, this.quality.shadowMapSize);
    }
    this.sun.shadow.bias = -0.0004;
    this.scene.add(this.sun, this.sun.target);

    this.controls = new OrbitControls(this.camera, canvas);
    // No gliding after a drag (its frames would draw on after the hand stopped): the camera
    // moves only while the hand or a key moves it, as prefers-reduced-motion asks.
    this.controls.enableDamping = false;
    this.controls.addEventListener("change", () => this.invalidate());
    canvas.addEventListener("keydown", (event) => this.onKey(event));

    this.resize = new ResizeObserver(() => this.fit());
    this.resize.observe(container);
    this.fit();
  }

  /** The camera back where it started for this rig. */
  resetView(): void {
    this.camera.position.copy(this.home.position);
    this.controls.target.copy(this.home.target);
    this.controls.update();
    this.invalidate();
  }

  /** Shows or cuts away the frame's near side (the wall between the camera and the rollers). */
  showNearSide(visible: boolean): void {
    this.nearSideShown = visible;
    if (this.model) this.model.nearSide.visible = visible;
    this.invalidate();
  }

  /** Builds the rig's bodies anew and frames them. */
  setRig(rig: Rig): void {
    if (this.model) {
      this.scene.remove(this.model.root);
      this.model.dispose();
    }
    if (this.arrows) {
      this.scene.remove(this.arrows.group);
      this.arrows.dispose();
    }
    this.model = buildRig(rig, this.quality);
    this.model.nearSide.visible = this.nearSideShown;
    this.arrows = new ForceArrows(rig);
    this.scene.add(this.model.root, this.arrows.group);
    void this.model.parts.then(() => this.invalidate());

    // Frame the rig: from the front (-y), a little above, its size filling the view.
    const size = Math.max(rig.plate.length, rig.spacing + 2 * rig.roller_radius, 0.08);
    const target = new THREE.Vector3(0, 0, -rig.roller_radius * 0.5);
    this.camera.position.set(0.2 * size, -1.45 * size, 0.8 * size).add(target);
    this.camera.near = size / 100;
    this.camera.far = size * 50;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(target);
    this.controls.minDistance = size * 0.2;
    this.controls.maxDistance = size * 10;
    this.controls.update();
    this.home.position.copy(this.camera.position);
    this.home.target.copy(target);
    this.pose = [];

    const reach = Math.max(size, 0.1);
    this.sun.position.set(0.3 * reach, -0.5 * reach, 1.5 * reach);
    this.sun.target.position.set(0, 0, 0);
    const shadow = this.sun.shadow.camera;
    shadow.left = shadow.bottom = -0.8 * reach;
    shadow.right = shadow.top = 0.8 * reach;
    shadow.near = 0.01;
    shadow.far = 4 * reach;
    shadow.updateProjectionMatrix();
    this.invalidate();
  }

  /** Poses the plate, turns the rollers and redraws the forces. */
  setState(state: LabState): void {
    if (!this.model || !this.arrows) return;
    const pose = [
      state.x,
      state.z,
      state.pitch,
      ...state.roller_angles,
      ...state.contacts.flatMap((c) => [c.normal, c.friction]),
    ];
    if (pose.length === this.pose.length && pose.every((v, i) => v === this.pose[i])) return;
    this.pose = pose;
    this.model.plate.position.set(state.x, 0, state.z);
    this.model.plate.rotation.set(0, state.pitch, 0);
    this.model.rollers[0].rotation.y = state.roller_angles[0];
    this.model.rollers[1].rotation.y = state.roller_angles[1];
    this.model.plateBlob?.position.setX(state.x);
    this.arrows.update(state);
    this.invalidate();
  }

  /** The view as a PNG data URL, drawn afresh. */
  toPng(): string {
    this.render();
    return this.renderer.domElement.toDataURL("image/png");
  }

  /** Draws once, at the next frame, however often it is asked before then. */
  invalidate(): void {
    if (!this.frame) this.frame = requestAnimationFrame(() => this.render());
  }

  dispose(): void {
    cancelAnimationFrame(this.frame);
    this.resize.disconnect();
    this.controls.dispose();
    this.model?.dispose();
    this.arrows?.dispose();
    this.renderer.dispose();
  }

  private fit(): void {
    const width = Math.max(1, this.container.clientWidth);
    const height = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(width, height, true);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  private onKey(event: KeyboardEvent): void {
    const move = cameraMoveOf(event);
    if (!move) return;
    event.preventDefault(); // the page does not scroll under the view's keys
    if (move.kind === "home") {
      this.resetView();
      return;
    }
    const reach = { min: this.controls.minDistance, max: this.controls.maxDistance };
    moveCamera(this.camera, this.controls.target, move, reach);
    this.controls.update();
    this.invalidate();
  }

  private render(): void {
    cancelAnimationFrame(this.frame);
    this.frame = 0;
    this.renderer.render(this.scene, this.camera);
    // For the page's tests: the frames drawn, and where the camera is from what it looks at.
    const canvas = this.renderer.domElement;
    canvas.dataset["frames"] = String(++this.frames);
    const offset = this.camera.position.clone().sub(this.controls.target);
    canvas.dataset["cameraDistanceMm"] = (offset.length() * 1000).toFixed(1);
    canvas.dataset["cameraAroundDeg"] = THREE.MathUtils.radToDeg(
      Math.atan2(offset.y, offset.x),
    ).toFixed(1);
  }
}
