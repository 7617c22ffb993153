// The rig's bodies as three.js objects in the lab's frame: z up, x along the plate's motion.
import * as THREE from "three";
import type { Rig } from "./lab_types";
import { placePart, srgbColor } from "./lego_parts";
import type { RenderQuality } from "./render_quality";

/** How each of Table I's plate materials looks (sRGB). */
const PLATE_LOOKS: Record<string, { color: number; opacity?: number; metalness?: number }> = {
  lego: { color: 0x9ba19d },
  paper: { color: 0xf4f2ea },
  "polished-wood": { color: 0xa86b3c },
  "construction-wood": { color: 0xc99b62 },
  iron: { color: 0x6e7073, metalness: 0.6 },
  plexiglas: { color: 0xcfe6f2, opacity: 0.6 },
  brass: { color: 0xc8a34a, metalness: 0.6 },
  cardboard: { color: 0xb58c5a },
  "rigid-foam": { color: 0xe8d98a },
  "flexible-foam": { color: 0xf0e2a8 },
};

export interface RigModel {
  root: THREE.Group;
  /** Posed each frame: its origin is the plate's centre of mass. */
  plate: THREE.Group;
  /** Roller 0 at x = -spacing/2, roller 1 at +spacing/2; each turns about +y. */
  rollers: [THREE.Object3D, THREE.Object3D];
  /** The height of the table the rig stands on. */
  groundZ: number;
  /** The plate's shadow blob on the table (software WebGL), posed under the plate each frame. */
  plateBlob: THREE.Object3D | null;
  /** Settles once every LEGO part is placed (or failed to load). */
  parts: Promise<void>;
  /**
   * The frame's parts wholly on the near side (y below the plate's near edge), where the camera
   * looks from: hidden unless asked for, as the video's front view cuts them away, so that the
   * rollers and the contacts show.
   */
  nearSide: THREE.Group;
  dispose: () => void;
}

class Owned {
  geometries: THREE.BufferGeometry[] = [];
  materials: THREE.Material[] = [];
  geometry<T extends THREE.BufferGeometry>(g: T): T {
    this.geometries.push(g);
    return g;
  }
  material<T extends THREE.Material>(m: T): T {
    this.materials.push(m);
    return m;
  }
  dispose(): void {
    for (const g of this.geometries) g.dispose();
    for (const m of this.materials) m.dispose();
  }
}

/** With a shadow map every body casts and receives shadows; with blobs, none does. */
class Shadows {
  constructor(private readonly map: boolean) {}
  body<T extends THREE.Mesh>(mesh: T): T {
    mesh.castShadow = mesh.receiveShadow = this.map;
    return mesh;
  }
  get partFlags() {
    return { castShadow: this.map, receiveShadow: this.map };
  }
}

/** A soft dark ellipse lying on the table: a shadow for software WebGL. */
function shadowBlob(owned: Owned, width: number, depth: number, material: THREE.Material) {
  const blob = new THREE.Mesh(owned.geometry(new THREE.PlaneGeometry(width, depth)), material);
  blob.renderOrder = 1;
  return blob;
}

function blobMaterial(owned: Owned): THREE.Material {
  const canvas = document.createElement("canvas");
  canvas.width = canvas.height = 64;
  const ctx = canvas.getContext("2d")!;
  const gradient = ctx.createRadialGradient(32, 32, 0, 32, 32, 32);
  gradient.addColorStop(0, "rgba(0,0,0,0.55)");
  gradient.addColorStop(0.6, "rgba(0,0,0,0.35)");
  gradient.addColorStop(1, "rgba(0,0,0,0)");
  ctx.fillStyle = gradient;
  ctx.fillRect(0, 0, 64, 64);
  const texture = new THREE.CanvasTexture(canvas);
  texture.colorSpace = THREE.SRGBColorSpace;
  const material = owned.material(
    new THREE.MeshBasicMaterial({ map: texture, transparent: true, depthWrite: false }),
  );
  material.addEventListener("dispose", () => texture.dispose());
  return material;
}

function makeRoller(
  rig: Rig,
  owned: Owned,
  shadows: Shadows,
  body: THREE.Material,
  marks: THREE.Material,
) {
  const r = rig.roller_radius;
  const roller = new THREE.Group();
  // CylinderGeometry's axis is y: the roller's axis.
  roller.add(
    shadows.body(
      new THREE.Mesh(owned.geometry(new THREE.CylinderGeometry(r, r, rig.roller_length, 40)), body),
    ),
  );
  // Two stripes along the roller, half a turn apart, so its turning shows.
  const stripe = owned.geometry(
    new THREE.BoxGeometry(0.3 * r, rig.roller_length * 1.004, 0.08 * r),
  );
  for (const side of [1, -1]) {
    const mark = new THREE.Mesh(stripe, marks);
    mark.position.z = side * r;
    roller.add(mark);
  }
  return roller;
}

export function buildRig(rig: Rig, quality: RenderQuality): RigModel {
  const owned = new Owned();
  const shadows = new Shadows(quality.shadows === "map");
  const root = new THREE.Group();
  root.name = `rig ${rig.scene}`;

  // Rollers: axes along y at x = -+spacing/2, z = -radius, so their tops touch z = 0.
  const pvc = owned.material(new THREE.MeshStandardMaterial({ color: 0xe9e9e4, roughness: 0.5 }));
  const stripe = owned.material(
    new THREE.MeshStandardMaterial({ color: 0x1f4e8c, roughness: 0.6 }),
  );
  const rollers: [THREE.Object3D, THREE.Object3D] = [
    makeRoller(rig, owned, shadows, pvc, stripe),
    makeRoller(rig, owned, shadows, pvc, stripe),
  ];
  rollers[0].position.set(-rig.spacing / 2, 0, -rig.roller_radius);
  rollers[1].position.set(rig.spacing / 2, 0, -rig.roller_radius);
  root.add(rollers[0], rollers[1]);

  // The plate: its origin at the centre of mass, its bottom face h_c below.
  const plate = new THREE.Group();
  plate.name = "plate";
  const p = rig.plate;
  const look = PLATE_LOOKS[p.material] ?? { color: 0xa0a0a0 };
  const slabMaterial = owned.material(
    new THREE.MeshStandardMaterial({
      color: look.color,
      roughness: 0.55,
      metalness: look.metalness ?? 0,
      transparent: look.opacity !== undefined,
      opacity: look.opacity ?? 1,
    }),
  );
  const slab = shadows.body(
    new THREE.Mesh(
      owned.geometry(new THREE.BoxGeometry(p.length, p.width, p.thickness)),
      slabMaterial,
    ),
  );
  slab.position.z = -p.h_c + p.thickness / 2;
  plate.add(slab);
  const topZ = -p.h_c + p.thickness;

  const magnetMaterial = owned.material(
    new THREE.MeshStandardMaterial({ color: 0x55585c, metalness: 0.7, roughness: 0.35 }),
  );
  for (const m of rig.magnets) {
    const magnet = shadows.body(
      new THREE.Mesh(
        owned.geometry(new THREE.CylinderGeometry(m.diameter / 2, m.diameter / 2, m.thickness, 24)),
        magnetMaterial,
      ),
    );
    magnet.rotation.x = Math.PI / 2; // axis along z
    magnet.position.set(m.x, 0, topZ + (m.height ?? 0) + m.thickness / 2);
    plate.add(magnet);
  }
  plate.position.set(rig.offset, 0, p.h_c);
  root.add(plate);

  if (rig.sensor) {
    const sensor = shadows.body(
      new THREE.Mesh(
        owned.geometry(new THREE.BoxGeometry(0.0045, 0.004, 0.0015)),
        owned.material(new THREE.MeshStandardMaterial({ color: 0x202124, roughness: 0.4 })),
      ),
    );
    sensor.name = "Hall sensor";
    sensor.position.set(rig.sensor.x, rig.sensor.y, rig.sensor.z);
    root.add(sensor);
  }

  const frameBottom = rig.frame.reduce((low, part) => Math.min(low, part.position[2]), Infinity);
  const groundZ = Math.min(frameBottom, -2 * rig.roller_radius - 0.004);
  // The table: Lambert shading and no larger than the rig needs, cheap for software WebGL.
  const tableSize = 2.4 * Math.max(p.length, rig.spacing + 4 * rig.roller_radius, 0.1);
  const ground = new THREE.Mesh(
    owned.geometry(new THREE.PlaneGeometry(tableSize, tableSize * 0.8)),
    owned.material(new THREE.MeshLambertMaterial({ color: 0xd9d4c7 })),
  );
  ground.position.z = groundZ;
  ground.receiveShadow = quality.shadows === "map";
  root.add(ground);

  let plateBlob: THREE.Object3D | null = null;
  if (quality.shadows === "blobs") {
    const dark = blobMaterial(owned);
    const lift = 0.0004; // above the table, below everything else
    plateBlob = shadowBlob(owned, p.length * 1.15, p.width * 1.6, dark);
    plateBlob.position.set(rig.offset, 0, groundZ + lift);
    root.add(plateBlob);
    for (const roller of rollers) {
      const blob = shadowBlob(owned, rig.roller_radius * 3, rig.roller_length * 1.15, dark);
      blob.position.set(roller.position.x, 0, groundZ + lift);
      root.add(blob);
    }
  }

  // LEGO parts: blocks stand on the plate's top face; the frame stands in the world.
  const placing: Promise<void>[] = [];
  for (const block of p.blocks) {
    placing.push(
      placePart(
        block.part,
        { position: [block.x, block.y, topZ], turnDeg: block.turn_deg, ...shadows.partFlags },
        owned.materials,
      ).then((part) => void plate.add(part)),
    );
  }
  const nearSide = new THREE.Group();
  nearSide.visible = false;
  root.add(nearSide);
  const nearEdge = -0.5 * p.width;
  for (const piece of rig.frame) {
    placing.push(
      placePart(
        piece.part,
        {
          position: piece.position,
          turnDeg: piece.turn_deg,
          color: piece.color ? srgbColor(piece.color) : null,
          ...shadows.partFlags,
        },
        owned.materials,
      ).then((part) => {
        const far = new THREE.Box3().setFromObject(part).max.y;
        (far < nearEdge ? nearSide : root).add(part);
      }),
    );
  }
  const parts = Promise.allSettled(placing).then(() => undefined);

  return {
    root,
    plate,
    rollers,
    groundZ,
    plateBlob,
    parts,
    nearSide,
    dispose: () => owned.dispose(),
  };
}
