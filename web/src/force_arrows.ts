// Force arrows: the normal and friction forces at the two contacts and the plate's weight,
// drawn to one scale, the weight m g about 3 cm long.
import * as THREE from "three";
import type { LabState, Rig } from "./lab_types";
import { FORCE_COLORS } from "./palette";

const G = 9.81; // m/s^2
const WEIGHT_LENGTH = 0.03; // m drawn for m g

function arrow(color: string): THREE.ArrowHelper {
  const helper = new THREE.ArrowHelper(
    new THREE.Vector3(0, 0, 1),
    new THREE.Vector3(),
    0.01,
    color,
  );
  for (const part of [helper.line, helper.cone]) {
    const material = part.material as THREE.Material;
    material.depthTest = false; // seen through the plate and its bricks
    material.transparent = true;
  }
  helper.renderOrder = 10;
  helper.visible = false;
  return helper;
}

function setArrow(
  helper: THREE.ArrowHelper,
  origin: THREE.Vector3,
  along: THREE.Vector3,
  length: number,
) {
  if (!(length > 1e-4)) {
    helper.visible = false;
    return;
  }
  helper.visible = true;
  helper.position.copy(origin);
  helper.setDirection(along);
  const head = Math.min(0.006, 0.35 * length);
  helper.setLength(length, head, 0.6 * head);
}

export class ForceArrows {
  readonly group = new THREE.Group();
  private readonly normals = [arrow(FORCE_COLORS.normal), arrow(FORCE_COLORS.normal)];
  private readonly frictions = [arrow(FORCE_COLORS.friction), arrow(FORCE_COLORS.friction)];
  private readonly weight = arrow(FORCE_COLORS.weight);
  private readonly metresPerNewton: number;
  private readonly contactX: [number, number];
  private readonly frontY: number;

  constructor(rig: Rig) {
    this.metresPerNewton = WEIGHT_LENGTH / (rig.plate.mass * G);
    this.contactX = [-rig.spacing / 2, rig.spacing / 2];
    this.frontY = -rig.plate.width / 2 - 0.003; // just in front of the plate, toward the camera
    this.group.name = "forces";
    this.group.add(...this.normals, ...this.frictions, this.weight);
  }

  update(state: LabState): void {
    const up = new THREE.Vector3(0, 0, 1);
    for (let i = 0; i < 2; i++) {
      const contact = state.contacts[i];
      const normal = this.normals[i]!;
      const friction = this.frictions[i]!;
      if (!contact) {
        normal.visible = friction.visible = false;
        continue;
      }
      const at = new THREE.Vector3(this.contactX[i], this.frontY, 0);
      setArrow(normal, at, up, contact.normal * this.metresPerNewton);
      const along = new THREE.Vector3(Math.sign(contact.friction) || 1, 0, 0);
      setArrow(friction, at, along, Math.abs(contact.friction) * this.metresPerNewton);
    }
    setArrow(
      this.weight,
      new THREE.Vector3(state.x, this.frontY, state.z),
      new THREE.Vector3(0, 0, -1),
      WEIGHT_LENGTH,
    );
  }

  dispose(): void {
    for (const helper of [...this.normals, ...this.frictions, this.weight]) helper.dispose();
  }
}
