// Three.js objects for the report's `scene` object (docs/report-schema.md#scene): link hulls
// (wireframe + shaded), their tolerance expansions, obstacles. Pure construction, no state.
import * as THREE from 'three';

export const COLORS = {
  background: 0xf4f5f7,
  linkWire: 0x1d3557,
  linkFill: 0x7fa7c9,
  expandedWire: 0xe09f3e,
  expandedFill: 0xf3c77b,
  obstacleWire: 0x2f4f2f,
  obstacleFill: 0x5fae5f,
  star: 0xe01010,
};

/// Triangle fan of every face loop (faces are convex, CCW from outside).
function meshGeometry(vertices, faces) {
  const positions = [];
  for (const loop of faces) {
    for (let k = 1; k + 1 < loop.length; ++k) {
      for (const index of [loop[0], loop[k], loop[k + 1]]) positions.push(...vertices[index]);
    }
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
  geometry.computeVertexNormals();
  return geometry;
}

function edgeGeometry(vertices, edges) {
  const positions = [];
  for (const [u, v] of edges) positions.push(...vertices[u], ...vertices[v]);
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
  return geometry;
}

/// One polytope as {wire, fill} objects sharing a parent.
function polytope(vertices, faces, edges, wireColor, fillColor, opacity) {
  const fill = new THREE.Mesh(
    meshGeometry(vertices, faces),
    new THREE.MeshPhongMaterial({
      color: fillColor,
      flatShading: true,
      transparent: opacity < 1,
      opacity,
      side: THREE.DoubleSide,
      depthWrite: opacity >= 1,
      polygonOffset: true,
      polygonOffsetFactor: 1,
      polygonOffsetUnits: 1,
    }),
  );
  const wire = new THREE.LineSegments(
    edgeGeometry(vertices, edges),
    new THREE.LineBasicMaterial({ color: wireColor }),
  );
  return { fill, wire };
}

/// Builds every object; links are THREE.Group with matrixAutoUpdate off (poses come from X_WL).
export function buildScene(scene) {
  const root = new THREE.Group();
  const links = [];
  const linkFills = [];
  const linkWires = [];
  const expanded = [];
  let hullCount = 0;
  for (const link of scene.links) {
    const group = new THREE.Group();
    group.matrixAutoUpdate = false;
    for (const hull of link.hulls) {
      const raw = polytope(hull.vertices_L, hull.faces, hull.edges, COLORS.linkWire, COLORS.linkFill, 1);
      const grown = polytope(
        hull.expanded.vertices_L, hull.expanded.faces, hull.expanded.edges,
        COLORS.expandedWire, COLORS.expandedFill, 0.28,
      );
      grown.fill.visible = grown.wire.visible = false;
      // What the pointer names on hover (main.js): link, hull and their names when the report has them.
      raw.fill.userData = { kind: 'link', link: link.link, hull: hull.hull, linkName: link.name ?? null,
        hullName: hull.name ?? null };
      group.add(raw.fill, raw.wire, grown.fill, grown.wire);
      linkFills.push(raw.fill);
      linkWires.push(raw.wire);
      expanded.push(grown.fill, grown.wire);
      ++hullCount;
    }
    root.add(group);
    links.push(group);
  }
  const obstacleFills = [];
  const obstacleWires = [];
  for (const obstacle of scene.obstacles) {
    const shape = polytope(obstacle.vertices_W, obstacle.faces, obstacle.edges,
      COLORS.obstacleWire, COLORS.obstacleFill, 0.75);
    shape.fill.userData = { kind: 'obstacle', obstacle: obstacle.obstacle, name: obstacle.name ?? null };
    root.add(shape.fill, shape.wire);
    obstacleFills.push(shape.fill);
    obstacleWires.push(shape.wire);
  }
  return { root, links, linkFills, linkWires, expanded, obstacleFills, obstacleWires, hullCount };
}

/// A red five-pointed star drawn on a canvas (no image files: the HTML is self-contained).
export function starTexture() {
  const size = 64;
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = size;
  const g = canvas.getContext('2d');
  g.beginPath();
  for (let k = 0; k < 10; ++k) {
    const radius = k % 2 === 0 ? size * 0.48 : size * 0.2;
    const angle = -Math.PI / 2 + (k * Math.PI) / 5;
    g.lineTo(size / 2 + radius * Math.cos(angle), size / 2 + radius * Math.sin(angle));
  }
  g.closePath();
  g.fillStyle = '#e01010';
  g.fill();
  g.lineWidth = 3;
  g.strokeStyle = '#600000';
  g.stroke();
  return new THREE.CanvasTexture(canvas);
}

/// Applies a row-major 4x4 pose (16 numbers) to a group.
export function setPose(group, rows) {
  group.matrix.set(...rows);
  group.matrixWorldNeedsUpdate = true;
}
