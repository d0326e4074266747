//! `linkage gears pair`: a meshing pair of involute spur gears from its module,
//! teeth, shifts and pressure angle (or a centre distance): every circle, tooth
//! thickness, the working pressure angle, centre distance, contact ratio and the
//! checks. Text in millimetres and degrees for a person; JSON in SI for programs.

use std::fmt::Write as _;

use linkage::gears::{
    CentreDistance, Gear, GearError, GearKind, GearPair, GearParam, GearSpec, PairIssue, PairSpec,
};
use linkage_diagram::numbers::significant;

use crate::args::{GearsCommand, PairArgs, ProfileArgs, ReportFormat};
use crate::error::{CliError, Result};

/// Runs `linkage gears …`.
pub(crate) fn run(what: GearsCommand) -> Result<String> {
    match what {
        GearsCommand::Pair(args) => pair(&args),
        GearsCommand::Profile(args) => profile(&args),
    }
}

/// `gears profile`: the cut gear's outline to SVG and DXF files; a line saying what
/// was written (and the undercut, where there is one; for a ring, how it was cut).
fn profile(a: &ProfileArgs) -> Result<String> {
    let spec = GearSpec {
        pressure_angle_rad: a.pressure_angle_deg.to_radians(),
        ..GearSpec::standard(a.module * 1e-3, a.teeth).shifted(a.shift)
    };
    let spec = if a.internal { spec.internal() } else { spec };
    let g = Gear::new(spec).map_err(|e| CliError::refused(words(&e)))?;
    if a.svg.is_none() && a.dxf.is_none() {
        return Err(CliError::refused("give --svg FILE or --dxf FILE"));
    }
    let mut said = String::new();
    let outline = if a.internal {
        let cut = ring_cut(&g, a.cutter_teeth)?;
        let _ = writeln!(
            said,
            "cut by a pinion cutter of {} teeth at a centre distance of {} mm, to a root \
             diameter of {} mm",
            a.cutter_teeth,
            significant(cut.centre_m * 1e3, 6),
            significant(2.0 * cut.cut_root_radius_m * 1e3, 6)
        );
        linkage_diagram::gear_profile::ring_outline(&g, a.cutter_teeth, 60)
    } else {
        linkage_diagram::gear_profile::gear_outline(&g, 60)
    };
    // Empty where the rack cuts nothing: its teeth pointed above their tip line.
    if outline.is_empty() {
        return Err(CliError::refused(format!(
            "at a pressure angle of {}° the basic rack's teeth (h_a* = 1, c* = 0.25) come to a \
             point before their tip line: no rack cuts this gear (the pressure angle must be \
             below 32.1°)",
            significant(a.pressure_angle_deg, 4)
        )));
    }
    if let Some(path) = &a.svg {
        let svg = linkage_diagram::gear_profile::gear_svg(&g, &outline);
        std::fs::write(path, svg).map_err(|source| CliError::Write {
            path: path.clone(),
            source,
        })?;
        let _ = writeln!(said, "wrote {}", path.display());
    }
    if let Some(path) = &a.dxf {
        write_dxf(path, &outline, g.pitch_radius_m)?;
        let _ = writeln!(said, "wrote {}", path.display());
    }
    if let Some(short) = g.undercut_shift_short() {
        let _ = writeln!(
            said,
            "undercut: the shift is {} short of x_min = {}",
            significant(short, 3),
            significant(g.least_shift_without_undercut(), 4)
        );
    }
    Ok(said)
}

/// How a pinion cutter of `cutter_teeth` cuts the ring `g`, or why it cannot.
fn ring_cut(g: &Gear, cutter_teeth: u32) -> Result<linkage::gears::shaper::ShaperCut> {
    linkage::gears::shaper::ShaperCut::new(g, cutter_teeth).ok_or_else(|| {
        CliError::refused(format!(
            "a pinion cutter of {cutter_teeth} teeth cannot cut a ring of {} teeth with a \
             shift of {}: the cutter needs 3 to {} teeth, and the shift a working pressure \
             angle (inv α' = inv α − 2 tan α x / (z − z_cutter) above 0)",
            g.spec.teeth,
            significant(g.spec.shift, 4),
            g.spec.teeth - 1
        ))
    })
}

#[cfg(not(target_arch = "wasm32"))]
fn write_dxf(path: &std::path::Path, outline: &[[f64; 2]], pitch_radius_m: f64) -> Result<()> {
    let error = |e: String| CliError::Write {
        path: path.to_path_buf(),
        source: std::io::Error::other(e),
    };
    let bytes = linkage_diagram::cam_dxf::gear_dxf(outline, pitch_radius_m)
        .map_err(|e| error(e.to_string()))?;
    std::fs::write(path, bytes).map_err(|e| error(e.to_string()))
}

/// The CLI is only type-checked for wasm32, where the DXF crate does not build.
#[cfg(target_arch = "wasm32")]
fn write_dxf(_: &std::path::Path, _: &[[f64; 2]], _: f64) -> Result<()> {
    Err(CliError::refused(
        "--dxf is not available in a wasm32 build",
    ))
}

fn pair(a: &PairArgs) -> Result<String> {
    let gear = |teeth: u32, shift: f64| GearSpec {
        module_m: a.module * 1e-3,
        teeth,
        pressure_angle_rad: a.pressure_angle_deg.to_radians(),
        addendum_coefficient: a.addendum,
        clearance_coefficient: a.clearance,
        shift,
        kind: GearKind::External,
    };
    let wheel = gear(a.teeth[1], a.shift[1]);
    let spec = PairSpec {
        pinion: gear(a.teeth[0], a.shift[0]),
        wheel: if a.internal { wheel.internal() } else { wheel },
        centre: a
            .centre_distance
            .map_or(CentreDistance::FromShifts, |mm| CentreDistance::Given {
                centre_m: mm * 1e-3,
            }),
    };
    let p = GearPair::new(spec).map_err(|e| CliError::refused(words(&e)))?;
    Ok(match a.format {
        ReportFormat::Json => serde_json::to_string_pretty(&p)? + "\n",
        ReportFormat::Text => text(&p),
    })
}

/// A length in metres as millimetres, four significant digits.
fn mm(m: f64) -> String {
    significant(m * 1e3, 4)
}

/// An angle in radians as degrees, five significant digits.
fn deg(rad: f64) -> String {
    format!("{}°", significant(rad.to_degrees(), 5))
}

/// The pair as a person reads it.
fn text(p: &GearPair) -> String {
    let mut out = String::new();
    let s = &p.pinion.spec;
    let kind = if p.internal { "internal" } else { "external" };
    let _ = writeln!(
        out,
        "{kind} pair: m = {} mm, α = {}, h_a* = {}, c* = {}",
        mm(s.module_m),
        deg(s.pressure_angle_rad),
        s.addendum_coefficient,
        s.clearance_coefficient
    );
    gear_rows(&mut out, p);
    pair_lines(&mut out, p);
    if p.issues.is_empty() {
        let _ = writeln!(out, "checks: none");
    }
    for issue in &p.issues {
        let _ = writeln!(out, "check: {}", issue_words(issue));
    }
    out
}

/// A row a gear: pinion and wheel side by side.
fn gear_rows(o: &mut String, p: &GearPair) {
    let _ = writeln!(o, "{:<44}{:>12}{:>12}", "", "pinion", "wheel");
    let row = |o: &mut String, name: &str, f: &dyn Fn(&Gear) -> String| {
        let _ = writeln!(o, "{name:<44}{:>12}{:>12}", f(&p.pinion), f(&p.wheel));
    };
    row(o, "teeth z", &|g| g.spec.teeth.to_string());
    row(o, "shift x", &|g| significant(g.spec.shift, 4));
    row(o, "pitch diameter d (mm)", &|g| mm(2.0 * g.pitch_radius_m));
    row(o, "base diameter d_b (mm)", &|g| mm(2.0 * g.base_radius_m));
    row(o, "tip diameter d_a (mm)", &|g| mm(2.0 * g.tip_radius_m));
    row(o, "root diameter d_f (mm)", &|g| mm(2.0 * g.root_radius_m));
    row(o, "tooth thickness on the pitch circle s (mm)", &|g| {
        mm(g.tooth_thickness_m)
    });
    row(o, "space width on the pitch circle e (mm)", &|g| {
        mm(g.space_width_m)
    });
    row(o, "tooth thickness at the tip s_a (mm)", &|g| {
        g.tip_thickness_m().map_or("-".into(), mm)
    });
    row(
        o,
        "least shift without undercut x_min",
        &|g| match g.spec.kind {
            GearKind::External => significant(g.least_shift_without_undercut(), 4),
            GearKind::Internal => "-".into(),
        },
    );
    let [r1, r2] = p.working_pitch_radii_m;
    let [c1, c2] = p.clearances_m;
    for (name, [a, b]) in [
        ("working pitch diameter d' (mm)", [2.0 * r1, 2.0 * r2]),
        ("clearance at the tip (mm)", [c1, c2]),
    ] {
        let _ = writeln!(o, "{name:<44}{:>12}{:>12}", mm(a), mm(b));
    }
}

/// The pair's own figures, one a line.
fn pair_lines(o: &mut String, p: &GearPair) {
    let line = |o: &mut String, name: &str, value: String| {
        let _ = writeln!(o, "{name:<44}{value:>12}");
    };
    line(o, "centre distance a' (mm)", mm(p.centre_m));
    line(
        o,
        "standard centre distance a (mm)",
        mm(p.standard_centre_m),
    );
    line(
        o,
        "working pressure angle α'",
        deg(p.working_pressure_angle_rad),
    );
    line(
        o,
        "centre distance modification y",
        significant(p.centre_modification, 4),
    );
    if let Some(dy) = p.tip_shortening {
        line(o, "tip shortening Δy", significant(dy, 4));
    }
    line(
        o,
        "shift sum without backlash",
        significant(p.shift_sum_without_backlash, 4),
    );
    line(
        o,
        "backlash on the working pitch circle (mm)",
        mm(p.backlash_m),
    );
    line(o, "path of contact g_α (mm)", mm(p.path_of_contact_m));
    line(o, "contact ratio ε_α", significant(p.contact_ratio, 4));
    line(
        o,
        "speed ratio (wheel / pinion)",
        significant(p.speed_ratio, 5),
    );
}

/// A check in words.
fn issue_words(issue: &PairIssue) -> String {
    match *issue {
        PairIssue::Undercut {
            member,
            shift_short,
        } => format!(
            "the {} is undercut by a rack cutter (its shift is {} short of the least)",
            member.words(),
            significant(shift_short, 3)
        ),
        PairIssue::PointedTip { member } => {
            format!(
                "the {}'s teeth come to a point inside the tip circle",
                member.words()
            )
        }
        PairIssue::ThinTip {
            member,
            thickness_m,
            least_m,
        } => format!(
            "the {}'s tip is {} mm thick, under 0.25·m = {} mm (0.4·m for hardened teeth)",
            member.words(),
            mm(thickness_m),
            mm(least_m)
        ),
        PairIssue::TipInterference { member } => format!(
            "the {}'s tip passes the other gear's interference point: it cuts into its root",
            member.words()
        ),
        PairIssue::RingTipInsideBase => {
            "the ring's tip circle is inside its base circle: its teeth are not involute to the tip"
                .into()
        }
        PairIssue::NoClearance {
            member,
            clearance_m,
        } => format!(
            "the {}'s tip meets the other gear's root (clearance {} mm)",
            member.words(),
            mm(clearance_m)
        ),
        PairIssue::ContactRatioBelowOne { contact_ratio } => format!(
            "contact ratio {} is below 1: the motion is not continuous",
            significant(contact_ratio, 4)
        ),
    }
}

/// A refusal in the units typed: millimetres and degrees.
fn words(e: &GearError) -> String {
    match *e {
        GearError::OutOfRange {
            member,
            param,
            value,
            min,
            max,
        } => {
            let (name, scale, unit) = match param {
                GearParam::Module => ("module", 1e3, " mm"),
                GearParam::PressureAngle => ("pressure angle", 180.0 / std::f64::consts::PI, "°"),
                other => (other.words(), 1.0, ""),
            };
            let who = member.map_or("gear", |m| m.words());
            let v = |x: f64| significant(x * scale, 4);
            format!(
                "{who}: {name} {}{unit} is outside the range {} … {}{unit}",
                v(value),
                v(min),
                v(max)
            )
        }
        GearError::CentreDistance {
            given_m,
            min_m,
            max_m,
            max_angle_deg,
        } => format!(
            "centre distance {} mm is outside the range {} … {} mm for these gears (working pressure angle 0 … {max_angle_deg}°)",
            mm(given_m),
            mm(min_m),
            mm(max_m)
        ),
        GearError::TeethJam {
            centre_m,
            overlap_m,
            shift_sum,
            shift_sum_max,
        } => format!(
            "at centre distance {} mm the teeth overlap by {} mm on the working pitch circle: the shifts must sum to at most {} (they sum to {})",
            mm(centre_m),
            mm(overlap_m),
            significant(shift_sum_max, 4),
            significant(shift_sum, 4)
        ),
        GearError::Mismatched { .. }
        | GearError::InternalPinion
        | GearError::RingTooSmall { .. }
        | GearError::NoRim { .. }
        | GearError::NoWorkingAngle { .. } => e.to_string(),
    }
}
