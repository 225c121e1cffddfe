// The colours of distance ranks, the same as the `drm` tool's and the
// MeshLab rank filter's (vcg_adapters/include/drm_vcg/rank_palette.h), so a
// picture means the same thing everywhere. Faces are coloured by the rank
// code that created them, bucketed as in the paper's Figure 1: the common
// rank 1 is quiet, rarer ranks are ever louder. Bucket 0 is a component's
// start triangle, which is stored, not ranked.

/** Buckets: start triangle, ranks 1, 2, 3, 4 and above. */
export const RANK_BUCKET_COUNT = 5;

function entry(r, g, b, colourName, label) {
  const hex = '#' + [r, g, b].map((v) => v.toString(16).padStart(2, '0')).join('');
  return Object.freeze({ r, g, b, colourName, label, hex });
}

/** One entry per bucket: {r, g, b, colourName, label, hex}. */
export const RANK_PALETTE = Object.freeze([
  entry(64, 64, 64, 'dark grey', 'start triangle'),
  entry(180, 192, 206, 'pale blue-grey', 'rank 1'),
  entry(76, 175, 80, 'green', 'rank 2'),
  entry(245, 166, 35, 'orange', 'rank 3'),
  entry(214, 39, 40, 'red', 'rank 4+'),
]);

/** The bucket of a rank code: 0 (start triangle) .. 4 (rank 4 and above). */
export function rankBucket(rank) {
  return rank >= 4 ? 4 : rank;
}

/** The palette entry of a rank code. */
export function rankColour(rank) {
  return RANK_PALETTE[rankBucket(rank)];
}
