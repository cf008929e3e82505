// The mesh a page carries: its JSON block read, its base64 arrays decoded into typed arrays,
// and the per-element lookups every other part of the viewer uses.

function decodeBase64(text, Type) {
  const binary = atob(text || '');
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  return new Type(bytes.buffer);
}

// The element blocks, each with its arrays decoded and its place in the page's element
// numbering: element `i` of a block is element `block.first + i` of the page, whose id (as a
// mesh file numbers it) is `block.firstId + i`.
function readBlocks(raw, families) {
  let first = 0;
  return raw.map((b) => {
    const family = families[b.family];
    const block = {
      type: b.type,
      family: b.family,
      dim: family.dim,
      corners: family.corners,
      faces: family.faces,
      edges: family.edges,
      entity: b.entity,
      groups: b.groups,
      count: b.count,
      firstId: b.firstId,
      first,
      nodes: decodeBase64(b.nodes, Uint32Array),
      quality: {},
      neighbours: b.neighbours ? decodeBase64(b.neighbours, Uint32Array) : null,
    };
    for (const [measure, text] of Object.entries(b.quality || {}))
      block.quality[measure] = decodeBase64(text, Float32Array);
    first += b.count;
    return block;
  });
}

// Element centroids, three coordinates each, in the page's element numbering.
function centroidsOf(blocks, positions, elementCount) {
  const centroids = new Float32Array(3 * elementCount);
  for (const block of blocks) {
    const k = block.corners;
    for (let i = 0; i < block.count; ++i) {
      const e = block.first + i;
      for (let c = 0; c < k; ++c) {
        const n = block.nodes[i * k + c];
        for (let d = 0; d < 3; ++d) centroids[3 * e + d] += positions[3 * n + d] / k;
      }
    }
  }
  return centroids;
}

function boundsOf(positions) {
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i += 3)
    for (let d = 0; d < 3; ++d) {
      min[d] = Math.min(min[d], positions[i + d]);
      max[d] = Math.max(max[d], positions[i + d]);
    }
  if (positions.length === 0) return { min: [0, 0, 0], max: [0, 0, 0] };
  return { min, max };
}

export function readMesh(doc = document) {
  const element = doc.getElementById('geomesh-mesh');
  if (!element) throw new Error('the page holds no mesh');
  const raw = JSON.parse(element.textContent);
  const positions = decodeBase64(raw.nodes, Float32Array);
  const blocks = readBlocks(raw.blocks, raw.families);
  const elementCount = blocks.reduce((sum, b) => sum + b.count, 0);
  const topDim = blocks.reduce((d, b) => Math.max(d, b.dim), 0);
  return {
    origin: raw.origin,
    positions,
    nodeCount: positions.length / 3,
    groups: raw.groups,
    groupsArePhysical: raw.groups.some((g) => g.physical),
    measures: raw.measures,
    counts: raw.counts,
    blocks,
    elementCount,
    topDim,
    bounds: boundsOf(positions),
    centroids: centroidsOf(blocks, positions, elementCount),
  };
}
