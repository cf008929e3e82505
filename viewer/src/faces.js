// What is drawn for a state of the controls: the kept elements (their group ticked, their
// centroid on the kept side of the clipping plane), the faces of kept surface elements, the
// faces of kept volume elements that no other kept volume element shares, and kept lines.

import { groupColor, qualityColor, kLineColorInQuality } from './colors.js';

// The group a block is drawn in: the first of its groups that is ticked; -1 when none is.
function shownGroup(block, groupOn) {
  for (const g of block.groups) if (groupOn[g]) return g;
  return -1;
}

function keptElements(mesh, state) {
  const kept = new Uint8Array(mesh.elementCount);
  const { axis, position, flip } = state.clip;
  for (const block of mesh.blocks) {
    if (shownGroup(block, state.groupOn) < 0) continue;
    for (let i = 0; i < block.count; ++i) {
      const e = block.first + i;
      if (axis >= 0) {
        const side = mesh.centroids[3 * e + axis] - position;
        if (flip ? side < 0 : side > 0) continue;
      }
      kept[e] = 1;
    }
  }
  return kept;
}

// Growable arrays of polygons: corners as node indices (3 or 4; the fourth is -1 for
// triangles), with an RGB colour each.
class PolygonList {
  constructor() {
    this.corners = [];
    this.colors = [];
    this.count = 0;
  }
  add(nodes, color) {
    this.corners.push(nodes[0], nodes[1], nodes[2], nodes.length > 3 ? nodes[3] : -1);
    this.colors.push(color[0], color[1], color[2]);
    this.count += 1;
  }
}

function elementColor(block, i, group, state) {
  if (state.mode !== 'quality') return groupColor(group);
  const q = block.quality[state.measure];
  return q ? qualityColor(q[i]) : kLineColorInQuality;
}

function addSurfaceElement(block, i, color, out) {
  const k = block.corners;
  out.add(Array.from(block.nodes.subarray(i * k, i * k + k)), color);
}

function addVolumeFaces(block, i, kept, color, out) {
  const k = block.corners;
  const faces = block.faces;
  for (let f = 0; f < faces.length; ++f) {
    const neighbour = block.neighbours ? block.neighbours[i * faces.length + f] : 0;
    if (neighbour !== 0 && kept[neighbour - 1]) continue;
    out.add(faces[f].map((c) => block.nodes[i * k + c]), color);
  }
}

export function visibleGeometry(mesh, state) {
  const kept = keptElements(mesh, state);
  const surfaces = new PolygonList();
  const volumes = new PolygonList();
  const lines = { nodes: [], colors: [] };
  for (const block of mesh.blocks) {
    const group = shownGroup(block, state.groupOn);
    if (group < 0 || block.dim === 0) continue;
    for (let i = 0; i < block.count; ++i) {
      if (!kept[block.first + i]) continue;
      const color = elementColor(block, i, group, state);
      if (block.dim === 1) {
        lines.nodes.push(block.nodes[i * block.corners], block.nodes[i * block.corners + 1]);
        const c = state.mode === 'quality' ? kLineColorInQuality : color;
        lines.colors.push(...c, ...c);
      } else if (block.dim === 2) {
        addSurfaceElement(block, i, color, surfaces);
      } else {
        addVolumeFaces(block, i, kept, color, volumes);
      }
    }
  }
  return { surfaces, volumes, lines, keptCount: kept.reduce((s, k) => s + k, 0) };
}
