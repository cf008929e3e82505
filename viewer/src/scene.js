// The 3D view: faces shaded with a headlight, element edges, lines, orbit controls, and the
// highlight of one element. Drawn on demand, never in a loop.

import {
  AmbientLight,
  BufferAttribute,
  BufferGeometry,
  Color,
  ColorManagement,
  DirectionalLight,
  DoubleSide,
  LinearSRGBColorSpace,
  LineBasicMaterial,
  LineSegments,
  Mesh,
  MeshLambertMaterial,
  PerspectiveCamera,
  Scene,
  Vector3,
  WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { LineMaterial } from 'three/addons/lines/LineMaterial.js';
import { LineSegments2 } from 'three/addons/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/addons/lines/LineSegmentsGeometry.js';
import { kEdgeColor } from './colors.js';

// Colours go to the screen as given, so that a group's colour is the one its swatch shows
// (shaded darker by the light, never shifted in hue).
ColorManagement.enabled = false;

function faceMaterial(offset) {
  return new MeshLambertMaterial({
    vertexColors: true,
    side: DoubleSide,
    polygonOffset: true,
    polygonOffsetFactor: offset,
    polygonOffsetUnits: offset,
  });
}

// Triangles of the polygons (quadrangles cut along 0-2), one vertex per corner so that each
// face is flat and has its own colour.
function fillFaces(geometry, polygons, positions) {
  let triangles = 0;
  for (let p = 0; p < polygons.count; ++p) triangles += polygons.corners[4 * p + 3] < 0 ? 1 : 2;
  const xyz = new Float32Array(9 * triangles);
  const rgb = new Float32Array(9 * triangles);
  let v = 0;
  const put = (node, p) => {
    for (let d = 0; d < 3; ++d) {
      xyz[3 * v + d] = positions[3 * node + d];
      rgb[3 * v + d] = polygons.colors[3 * p + d];
    }
    v += 1;
  };
  for (let p = 0; p < polygons.count; ++p) {
    const c = polygons.corners.slice(4 * p, 4 * p + 4);
    put(c[0], p), put(c[1], p), put(c[2], p);
    if (c[3] >= 0) put(c[0], p), put(c[2], p), put(c[3], p);
  }
  geometry.setAttribute('position', new BufferAttribute(xyz, 3));
  geometry.setAttribute('color', new BufferAttribute(rgb, 3));
  geometry.computeVertexNormals();
  geometry.computeBoundingSphere();
}

function fillSegments(geometry, nodes, positions) {
  const xyz = new Float32Array(3 * nodes.length);
  nodes.forEach((n, i) => xyz.set(positions.subarray(3 * n, 3 * n + 3), 3 * i));
  geometry.setAttribute('position', new BufferAttribute(xyz, 3));
  geometry.computeBoundingSphere();
}

// The edges of the polygons, each polygon's sides.
function polygonEdges(polygons, into) {
  for (let p = 0; p < polygons.count; ++p) {
    const c = polygons.corners.slice(4 * p, 4 * p + 4);
    const k = c[3] < 0 ? 3 : 4;
    for (let i = 0; i < k; ++i) into.push(c[i], c[(i + 1) % k]);
  }
}

export class MeshView {
  constructor(canvas, mesh) {
    this.mesh = mesh;
    this.canvas = canvas;
    this.renderer = new WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
    this.renderer.outputColorSpace = LinearSRGBColorSpace;
    this.renderer.setClearColor(0xf4f4f6);
    this.scene = new Scene();
    this.camera = new PerspectiveCamera(35, 1, 0.01, 100);
    this.scene.add(new AmbientLight(0xffffff, 0.4 * Math.PI));
    this.headlight = new DirectionalLight(0xffffff, 0.6 * Math.PI);
    this.camera.add(this.headlight);
    this.headlight.position.set(0, 0, 1);
    this.scene.add(this.camera);
    this.surfaces = new Mesh(new BufferGeometry(), faceMaterial(1));
    this.volumes = new Mesh(new BufferGeometry(), faceMaterial(2));
    this.edges = new LineSegments(
      new BufferGeometry(),
      new LineBasicMaterial({ color: new Color().setRGB(...kEdgeColor) }),
    );
    // Lines (curve elements) are drawn wide, in pixels, so that a curve group stands out.
    this.lines = new LineSegments2(
      new LineSegmentsGeometry(),
      new LineMaterial({ vertexColors: true, linewidth: 3, worldUnits: false }),
    );
    this.lines.renderOrder = 1;
    this.highlight = new LineSegments(
      new BufferGeometry(),
      new LineBasicMaterial({ color: 0x000000, depthTest: false }),
    );
    this.highlight.renderOrder = 2;
    this.scene.add(this.surfaces, this.volumes, this.edges, this.lines, this.highlight);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.addEventListener('change', () => this.render());
    this.fit();
  }

  // Looks at the whole mesh: from +z for a flat mesh in the xy plane, else from a corner.
  fit() {
    const { min, max } = this.mesh.bounds;
    const center = new Vector3((min[0] + max[0]) / 2, (min[1] + max[1]) / 2, (min[2] + max[2]) / 2);
    const diagonal = Math.hypot(max[0] - min[0], max[1] - min[1], max[2] - min[2]);
    const radius = Math.max(1e-9, 0.5 * diagonal);
    const flat = max[2] - min[2] <= 1e-6 * radius;
    const direction = flat ? new Vector3(0, 0, 1) : new Vector3(1, -1.4, 0.9).normalize();
    const distance = radius / Math.sin((this.camera.fov * Math.PI) / 360);
    this.camera.near = distance / 100;
    this.camera.far = distance * 100;
    this.camera.up.set(0, flat ? 1 : 0, flat ? 0 : 1);
    this.camera.position.copy(center).addScaledVector(direction, distance * 1.05);
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(center);
    this.controls.update();
    this.radius = radius;
  }

  resize() {
    const width = this.canvas.clientWidth;
    const height = this.canvas.clientHeight;
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setSize(width, height, false);
    this.camera.aspect = width / Math.max(1, height);
    this.camera.updateProjectionMatrix();
    this.lines.material.resolution.set(width, height);
    this.render();
  }

  show(geometry, showEdges) {
    const positions = this.mesh.positions;
    fillFaces(this.surfaces.geometry, geometry.surfaces, positions);
    fillFaces(this.volumes.geometry, geometry.volumes, positions);
    const edgeNodes = [];
    if (showEdges) {
      polygonEdges(geometry.surfaces, edgeNodes);
      polygonEdges(geometry.volumes, edgeNodes);
    }
    fillSegments(this.edges.geometry, edgeNodes, positions);
    const lines = new LineSegmentsGeometry();
    const ends = new Float32Array(3 * geometry.lines.nodes.length);
    geometry.lines.nodes.forEach((n, i) => ends.set(positions.subarray(3 * n, 3 * n + 3), 3 * i));
    lines.setPositions(ends);
    lines.setColors(new Float32Array(geometry.lines.colors));
    this.lines.geometry.dispose();
    this.lines.geometry = lines;
    this.render();
  }

  // Centres the view on an element and outlines it; null clears the outline.
  focus(corners, edges) {
    const nodes = [];
    if (corners) for (const [a, b] of edges) nodes.push(corners[a], corners[b]);
    fillSegments(this.highlight.geometry, nodes, this.mesh.positions);
    if (corners) {
      const p = this.mesh.positions;
      const center = new Vector3();
      for (const n of corners) center.add(new Vector3(p[3 * n], p[3 * n + 1], p[3 * n + 2]));
      center.divideScalar(corners.length);
      const offset = this.camera.position.clone().sub(this.controls.target);
      this.controls.target.copy(center);
      this.camera.position.copy(center).add(offset.multiplyScalar(0.5));
      this.controls.update();
    }
    this.render();
  }

  render() {
    this.renderer.render(this.scene, this.camera);
  }
}
