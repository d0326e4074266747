// Whether the page kept drawing while work ran in slices off the frame, judged with
// no figure that depends on the machine's speed: no count of frames, no wall time.
// A page that froze holds the whole search inside one gap between frames; one that
// slices it shows gaps of a frame and a slice each. So the largest gap is judged
// against the span of the frames the search ran through, and only where that span
// is several of the page's frames long (a search done within a few frames cannot
// have held the page longer than those frames). Every gap scaled by the same factor
// (a slower or a busier machine) gets the same verdict.

/** The median of `xs` (NaN for none). */
export function median(xs) {
  if (!xs.length) return NaN;
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : 0.5 * (s[m - 1] + s[m]);
}

/** Searches that span fewer of the page's frames (median gaps) are not judged. */
export const JUDGED_FROM_FRAMES = 4;

/** The verdict on a search during which the page drew frames `gaps` ms apart (from
 * the click that started it to the frame that showed it stopped): `{ judged, ok,
 * why }`. */
export function framesKeptComing(gaps) {
  if (!gaps.length) return { judged: false, ok: false, why: 'no frames were measured' };
  const frame = median(gaps);
  const span = gaps.reduce((a, b) => a + b, 0);
  if (span < JUDGED_FROM_FRAMES * frame) {
    return { judged: false, ok: true, why: `the search spanned ${span.toFixed(0)} ms, under ${JUDGED_FROM_FRAMES} frames of ${frame.toFixed(0)} ms` };
  }
  const worst = Math.max(...gaps);
  const ok = worst <= 0.5 * span;
  const why = `the largest gap between frames, ${worst.toFixed(0)} ms, is ${ok ? 'at most' : 'more than'} half the ${span.toFixed(0)} ms the search spanned (frames of ${frame.toFixed(0)} ms)`;
  return { judged: true, ok, why };
}

/** The page's frames the search has spanned so far, in its median frames. */
export function framesSpanned(gaps) {
  return gaps.length ? gaps.reduce((a, b) => a + b, 0) / median(gaps) : 0;
}

/** Whether each slice ended at its first step past the budget (the slices' record
 * as the app publishes it): `{ ok, why }`. */
export function slicesKeptTheirBudget({ slice_budget_ms: budget, slices }) {
  const bound = budget + slices.longest_step_ms;
  const ok = slices.longest_ms <= bound;
  return { ok, why: `the longest of ${slices.count} slices took ${slices.longest_ms.toFixed(1)} ms; the budget and one step allow ${bound.toFixed(1)} ms` };
}
