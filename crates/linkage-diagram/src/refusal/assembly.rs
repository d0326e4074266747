//! A chain that does not close, in words: what falls short (two links that cannot
//! meet, a guide out of reach) with its lengths, and where the crank can go.

use linkage::assembly::AssemblyRanges;
use linkage::dyad::{DyadLabel, Shortfall, pair_name};
use linkage::scene::LengthUnit;

use super::length;
use crate::numbers::significant;
use crate::words::{Lang, sw};

/// A dyad that does not close: what falls short, or its links by name.
pub fn open(
    lang: Lang,
    dyad: &DyadLabel,
    shortfall: Option<&Shortfall>,
    unit: LengthUnit,
) -> String {
    let Some(s) = shortfall else {
        let [a, b] = &dyad.links;
        return sw!(
            lang,
            "refusal.cannot_join",
            a = a,
            b = b,
            joint = dyad.inner_point
        );
    };
    let len = |m: f64| length(m, unit);
    match s {
        Shortfall::Apart {
            ends: [a, c],
            inner,
            lengths: [l1, l2],
            apart,
        } => {
            let why = if *apart > l1 + l2 {
                sw!(lang, "refusal.more_than_sum", sum = len(l1 + l2))
            } else {
                sw!(
                    lang,
                    "refusal.less_than_difference",
                    difference = len((l1 - l2).abs())
                )
            };
            sw!(
                lang,
                "refusal.cannot_meet",
                ab = pair_name(a, inner),
                ab_length = len(*l1),
                cb = pair_name(c, inner),
                cb_length = len(*l2),
                inner = inner,
                a = a,
                c = c,
                apart = len(*apart),
                why = why
            )
        }
        Shortfall::Guide {
            end,
            inner,
            length: l,
            offset,
        } => sw!(
            lang,
            "refusal.guide_out_of_reach",
            link = pair_name(end, inner),
            length = len(*l),
            inner = inner,
            end = end,
            offset = len(*offset)
        ),
        Shortfall::Slot {
            guide_pin,
            slider_pin,
            offset,
            apart,
        } => sw!(
            lang,
            "refusal.slot_misses",
            guide_pin = guide_pin,
            slider_pin = slider_pin,
            apart = len(*apart),
            offset = len(*offset)
        ),
    }
}

/// Where the crank can go, in degrees.
pub fn reach(lang: Lang, r: &AssemblyRanges) -> String {
    if r.full_rotation {
        return sw!(lang, "refusal.full_turn");
    }
    if r.intervals.is_empty() {
        return sw!(lang, "refusal.no_angle");
    }
    let spans: Vec<String> = r
        .intervals
        .iter()
        .map(|[a, b]| {
            sw!(
                lang,
                "refusal.span",
                from = significant(a.to_degrees(), 5),
                to = significant(b.to_degrees(), 5)
            )
        })
        .collect();
    sw!(
        lang,
        "refusal.crank_reaches",
        spans = spans.join(&sw!(lang, "refusal.or"))
    )
}
