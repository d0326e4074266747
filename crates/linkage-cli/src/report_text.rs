//! `linkage report --format text`: the report as a person at a terminal reads it, in
//! the scene's length unit and degrees, values to four significant digits with their
//! units and prefixes; each output's largest speed and acceleration located with the
//! crank angle where it is, or, where the input's range ends at dead points, said to
//! be unbounded there. The JSON stays SI for programs.

use std::fmt::Write as _;

use linkage::analysis::{OutputPeaks, Peak, Report};
use linkage::scene::LengthUnit;
use linkage_diagram::numbers::{si, significant};

/// Degrees of an angle in radians, four significant digits.
fn deg(rad: f64) -> String {
    format!("{}°", significant(rad.to_degrees(), 4))
}

/// A crank angle in degrees in [0, 360), five significant digits (a round-off
/// from zero written as 0).
fn crank(rad: f64) -> String {
    let d = rad.to_degrees().rem_euclid(360.0);
    let d = if d < 1e-9 || 360.0 - d < 1e-9 { 0.0 } else { d };
    format!("{}°", significant(d, 5))
}

/// A length in metres, in the scene's unit.
fn length(m: f64, unit: LengthUnit) -> String {
    let symbol = match unit {
        LengthUnit::Metre => "m",
        LengthUnit::Millimetre => "mm",
    };
    format!("{} {symbol}", significant(m / unit.to_metres(), 4))
}

/// The report and the outputs' peaks as text.
pub(crate) fn text(r: &Report, peaks: &[OutputPeaks], unit: LengthUnit) -> String {
    let mut out = String::new();
    let line = &mut out;
    let _ = writeln!(line, "{}", r.name);
    let rpm = r.input_speed_rad_s * 60.0 / std::f64::consts::TAU;
    let _ = writeln!(
        line,
        "input: {} rpm ({} rad/s), {}; solver: {}",
        significant(rpm, 4),
        significant(r.input_speed_rad_s, 4),
        input_range(r),
        r.solver_path.label()
    );
    grashof(line, r, unit);
    let _ = match r.time_ratio {
        Some(k) => writeln!(line, "time ratio K = {}", significant(k, 4)),
        None => writeln!(line, "time ratio K: none (no output with a return stroke)"),
    };
    if let Some(note) = &r.time_ratio_note {
        let _ = writeln!(line, "  {note}");
    }
    for (name, stroke) in &r.strokes_m {
        let _ = writeln!(line, "stroke of {name}: {}", length(*stroke, unit));
    }
    for (name, swing) in &r.swings_rad {
        let _ = writeln!(line, "swing of {name}: {}", deg(*swing));
    }
    for l in &r.limit_positions {
        let value = if r.swings_rad.contains_key(&l.output) {
            deg(l.value)
        } else {
            length(l.value, unit)
        };
        let _ = writeln!(
            line,
            "  {} {} = {value} at crank {}",
            l.output,
            l.kind,
            crank(l.input_rad)
        );
    }
    if let Some(t) = &r.transmission_angle_rad {
        let _ = writeln!(
            line,
            "transmission angle: least {} at crank {}, largest {} at crank {}",
            deg(t.min),
            crank(t.at),
            deg(t.max),
            crank(t.at_max)
        );
    }
    for p in peaks {
        output_peaks(line, p);
    }
    for t in &r.toggles {
        toggle(line, t);
    }
    out
}

/// A toggle in words: an output at rest (a limit position) or the input at a dead
/// point, with the joints whose links lie in line there.
fn toggle(line: &mut String, t: &linkage::analysis::Toggle) {
    let joints: Vec<&str> = t
        .collinear_joints
        .iter()
        .map(|j| j.point.as_str())
        .collect();
    let in_line = if joints.is_empty() {
        String::new()
    } else {
        format!("; links in line at {}", joints.join(", "))
    };
    let _ = if t.ratio == linkage::analysis::ToggleRatio::Infinite {
        writeln!(
            line,
            "dead point of the input at crank {}{in_line}",
            crank(t.input_rad)
        )
    } else {
        writeln!(
            line,
            "{} at rest (a limit position) at crank {}{in_line}",
            t.output,
            crank(t.input_rad)
        )
    };
}

/// The input's range: a full turn, or between its dead points.
fn input_range(r: &Report) -> String {
    if r.full_rotation {
        return "turns a full circle".into();
    }
    let spans: Vec<String> = r
        .assembly_range_rad
        .iter()
        .map(|[a, b]| format!("{} to {}", crank(*a), crank(*b)))
        .collect();
    format!("rocks between dead points, {}", spans.join(" or "))
}

fn grashof(line: &mut String, r: &Report, unit: LengthUnit) {
    let Some(g) = &r.grashof else {
        return;
    };
    let lengths: Vec<String> = g
        .links
        .iter()
        .zip(&g.lengths_m)
        .map(|(name, l)| format!("{name} {}", length(*l, unit)))
        .collect();
    let _ = writeln!(
        line,
        "Grashof: {} (s + l = {}, p + q = {}; {})",
        g.class,
        length(g.s_plus_l_m, unit),
        length(g.p_plus_q_m, unit),
        lengths.join(", ")
    );
}

/// An output's largest speed and acceleration, or why they have none.
fn output_peaks(line: &mut String, p: &OutputPeaks) {
    let value = |v: f64, order: i32| -> String {
        if p.is_angle {
            let suffix = if order == 1 { "rad/s" } else { "rad/s²" };
            format!("{} {suffix}", significant(v, 4))
        } else {
            si(v, if order == 1 { "m/s" } else { "m/s²" })
        }
    };
    for (what, peak, order) in [("speed", p.speed, 1), ("acceleration", p.acceleration, 2)] {
        let _ = match peak {
            Peak::At(e) => writeln!(
                line,
                "largest {what} of {}: {} at crank {}",
                p.output,
                value(e.value, order),
                crank(e.angle_rad)
            ),
            Peak::Unbounded { dead_points_rad } => writeln!(
                line,
                "largest {what} of {}: unbounded: the input's range ends at dead points, crank {} and {}",
                p.output,
                crank(dead_points_rad[0]),
                crank(dead_points_rad[1])
            ),
        };
    }
}
