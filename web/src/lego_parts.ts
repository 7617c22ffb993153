// LEGO parts from /parts/NAME.glb, loaded once each and placed in the lab's z-up world.
import * as THREE from "three";
import { GLTFLoader } from "three/examples/jsm/loaders/GLTFLoader.js";
import { partUrl } from "./lab_client";

const loader = new GLTFLoader();
const templates = new Map<string, Promise<THREE.Object3D>>();

function template(name: string): Promise<THREE.Object3D> {
  let loading = templates.get(name);
  if (!loading) {
    loading = loader.loadAsync(partUrl(name)).then((gltf) => gltf.scene);
    loading.catch(() => templates.delete(name));
    templates.set(name, loading);
  }
  return loading;
}

/** An sRGB colour as the lab sends it: components in 0..1 (or 0..255, read as such). */
export function srgbColor(rgb: readonly [number, number, number]): THREE.Color {
  const scale = rgb.some((c) => c > 1) ? 1 / 255 : 1;
  return new THREE.Color().setRGB(
    rgb[0] * scale,
    rgb[1] * scale,
    rgb[2] * scale,
    THREE.SRGBColorSpace,
  );
}

export interface PartPose {
  position: readonly [number, number, number];
  turnDeg: number;
  color?: THREE.Color | null;
  castShadow: boolean;
  receiveShadow: boolean;
}

/**
 * A part posed in its parent's z-up frame: glTF is y-up, so the mesh sits in a group turned
 * +pi/2 about x (a vertex (x, y, z) lands at (x, -z, y)); that group is placed at the pose's
 * position and turned turn_deg about z. Materials made for a colour are listed in `owned`.
 */
export async function placePart(
  name: string,
  pose: PartPose,
  owned: THREE.Material[],
): Promise<THREE.Group> {
  const mesh = (await template(name)).clone(true);
  mesh.traverse((node) => {
    if (!(node instanceof THREE.Mesh)) return;
    node.castShadow = pose.castShadow;
    node.receiveShadow = pose.receiveShadow;
    if (pose.color && node.material instanceof THREE.MeshStandardMaterial) {
      const material = node.material.clone();
      material.color.copy(pose.color);
      owned.push(material);
      node.material = material;
    }
  });
  const zUp = new THREE.Group();
  zUp.rotation.x = Math.PI / 2;
  zUp.add(mesh);
  const placed = new THREE.Group();
  placed.name = name;
  placed.position.set(pose.position[0], pose.position[1], pose.position[2]);
  placed.rotation.z = THREE.MathUtils.degToRad(pose.turnDeg);
  placed.add(zUp);
  return placed;
}
