//! The course-design report (课程设计说明书) on A4 pages, in the reader's language:
//! the title and the task's data, the structural analysis, the positions table and
//! the course sheet's figures with their vector-equation tables and force polygons,
//! the flywheel, the cams and the results table. The data is
//! [`crate::course_report::CourseReport`]'s.

use linkage::analysis::GrashofClass;
use linkage::dyad::GroupLabel;

use crate::course_report::{CourseReport, REPORT_DELTA};
use crate::numbers::{degrees, si, significant};
use crate::pages::{Pages, Sheet, heading};
use crate::svg_draw::{FONT, MARGIN, PAGE_W, fit_text, text_at};
use crate::words::{self, Lang, sw};

/// A table's row height, px: a line of Chinese is 1.45 em.
const ROW: f64 = 1.75 * FONT;
/// The width between the margins, px.
const WIDTH: f64 = PAGE_W - 2.0 * MARGIN;

/// The report in `lang`.
pub fn course_report(r: &CourseReport, lang: Lang) -> Sheet {
    let m = &r.course.mechanism;
    let title = sw!(
        lang,
        "report.footer",
        title = sw!(lang, "report.title"),
        name = m.name
    );
    let mut pages = Pages::new(&title);
    heading(&mut pages, &sw!(lang, "report.title"), 22.0);
    heading(
        &mut pages,
        &sw!(lang, "report.subject", name = m.name),
        16.0,
    );
    line(&mut pages, &sw!(lang, "report.made_by"));
    task(&mut pages, r, lang);
    structure(&mut pages, r, lang);
    kinematics(&mut pages, r, lang);
    flywheel(&mut pages, r, lang);
    cams(&mut pages, r, lang);
    results(&mut pages, r, lang);
    pages.finish()
}

/// A numbered section's heading: "3 运动分析与力分析", numbered in the order the
/// report holds them (a scene without cams has no cam section to count).
fn section(pages: &mut Pages, title: &str) {
    let n = pages.next_section();
    heading(pages, &format!("{n} {title}"), 14.0);
}

/// A line of text, cut to the page's width.
fn line(pages: &mut Pages, text: &str) {
    let top = pages.place(ROW);
    let fitted = fit_text(text, WIDTH, FONT);
    text_at(
        pages.out(),
        [MARGIN, top + ROW - 5.0],
        &fitted,
        FONT,
        "normal",
    );
}

/// A table: its head in bold, then its rows, each whole on a page.
fn table(pages: &mut Pages, columns: &[f64], head: &[String], rows: &[Vec<String>]) {
    let widths: Vec<f64> = columns
        .iter()
        .zip(columns.iter().skip(1).chain(std::iter::once(&WIDTH)))
        .map(|(a, b)| b - a - 8.0)
        .collect();
    // A table without a head (all its names empty) starts with its first row.
    let head = (!head.iter().all(String::is_empty)).then_some(head);
    let all = head.into_iter().chain(rows.iter().map(Vec::as_slice));
    for (i, cells) in all.enumerate() {
        let top = pages.place(ROW);
        let weight = if i == 0 && head.is_some() {
            "bold"
        } else {
            "normal"
        };
        for ((x, w), cell) in columns.iter().zip(&widths).zip(cells) {
            let at = [MARGIN + x, top + ROW - 5.0];
            text_at(pages.out(), at, &fit_text(cell, *w, FONT), FONT, weight);
        }
    }
}

/// §1: the crank speed, the links and the scene's notes.
fn task(pages: &mut Pages, r: &CourseReport, lang: Lang) {
    section(pages, &sw!(lang, "report.task"));
    let omega = r.course.mechanism.driver.speed_rad_s;
    let rpm = omega * 60.0 / std::f64::consts::TAU;
    let speed = sw!(
        lang,
        "report.speed",
        omega = significant(omega, 4),
        rpm = significant(rpm, 4)
    );
    line(pages, &speed);
    let head = [
        sw!(lang, "report.col_link"),
        sw!(lang, "report.col_name"),
        sw!(lang, "report.col_lengths"),
    ];
    let rows: Vec<Vec<String>> = r
        .links
        .iter()
        .map(|l| {
            let lengths: Vec<String> = l
                .lengths_m
                .iter()
                .map(|(name, v)| format!("{name} = {}", si(*v, "m")))
                .collect();
            vec![l.number.to_string(), l.name.clone(), lengths.join(", ")]
        })
        .collect();
    table(pages, &[0.0, 60.0, 220.0], &head, &rows);
    if !r.analysis.notes.is_empty() {
        line(pages, &sw!(lang, "report.notes"));
        for note in &r.analysis.notes {
            for part in crate::pages::wrap(note, WIDTH, FONT) {
                line(pages, &part);
            }
        }
    }
}

/// §2: the degrees of freedom and the Assur groups.
fn structure(pages: &mut Pages, r: &CourseReport, lang: Lang) {
    section(pages, &sw!(lang, "report.structure"));
    let f = r.mobility;
    let dof = sw!(
        lang,
        "report.dof",
        n = f.moving,
        pl = f.lower,
        ph = f.higher,
        f = f.dof
    );
    line(pages, &dof);
    line(pages, &sw!(lang, "report.groups"));
    let rows: Vec<Vec<String>> = r
        .groups
        .iter()
        .enumerate()
        .map(|(i, g)| {
            let class = match g {
                GroupLabel::Dyad(_) => sw!(lang, "report.dyad_class"),
                GroupLabel::Numbered(_) => sw!(lang, "report.numbered_class"),
            };
            vec![format!("{}", i + 1), words::group(lang, g), class]
        })
        .collect();
    table(pages, &[0.0, 30.0, 400.0], &[], &rows);
    if r.groups.iter().all(|g| matches!(g, GroupLabel::Dyad(_))) {
        line(pages, &sw!(lang, "report.class_two"));
    }
}

/// §3: the positions table, then the course sheet's figures and tables.
fn kinematics(pages: &mut Pages, r: &CourseReport, lang: Lang) {
    pages.new_page();
    section(pages, &sw!(lang, "report.kinematics"));
    if let Some((name, is_angle)) = &r.output {
        let of = sw!(
            lang,
            "report.positions_of",
            name = name,
            count = r.positions.len()
        );
        line(pages, &of);
        let units: [&str; 3] = if *is_angle {
            ["rad", "rad/s", "rad/s²"]
        } else {
            ["m", "m/s", "m/s²"]
        };
        // One unit a column, its prefix chosen by the column's largest value.
        let columns: [Column; 3] = std::array::from_fn(|i| {
            let scale = r
                .positions
                .iter()
                .map(|p| p.s_v_a[i].abs())
                .fold(0.0, f64::max);
            Column::new(scale, units[i], *is_angle && i == 0)
        });
        let names = [
            sw!(lang, "report.col_s"),
            sw!(lang, "report.col_v"),
            sw!(lang, "report.col_a"),
        ];
        let mut head = vec![
            sw!(lang, "report.col_position"),
            sw!(lang, "report.col_crank"),
        ];
        for (c, key) in columns.iter().zip(names) {
            head.push(format!("{key} ({})", c.unit));
        }
        let rows: Vec<Vec<String>> = r
            .positions
            .iter()
            .map(|p| {
                let mut row = vec![p.number.to_string(), degrees(p.crank_deg)];
                row.extend(columns.iter().zip(p.s_v_a).map(|(c, v)| c.cell(v)));
                row
            })
            .collect();
        table(pages, &[0.0, 70.0, 180.0, 340.0, 500.0], &head, &rows);
    }
    crate::svg_course::course_body(pages, &r.course, lang, true);
}

/// A column of the positions table: its unit with the prefix its largest value takes
/// (a rocker's angle in degrees), and the size its round-off is judged against.
struct Column {
    unit: String,
    factor: f64,
    scale: f64,
}

impl Column {
    fn new(scale: f64, unit: &str, degrees: bool) -> Self {
        if degrees {
            return Self {
                unit: "°".into(),
                factor: 180.0 / std::f64::consts::PI,
                scale,
            };
        }
        let p = crate::numbers::Prefix::for_magnitude(scale);
        Self {
            unit: p.unit(unit),
            factor: p.factor,
            scale,
        }
    }

    /// `v` in the column's unit, four significant digits, its round-off as 0.
    fn cell(&self, v: f64) -> String {
        if v.abs() <= self.scale * crate::numbers::ROUND_OFF {
            return "0".into();
        }
        significant(v * self.factor, 4)
    }
}

/// §4: the flywheel sized by the energy method.
fn flywheel(pages: &mut Pages, r: &CourseReport, lang: Lang) {
    pages.keep(8.0 * ROW);
    section(pages, &sw!(lang, "report.flywheel"));
    let Some(f) = &r.flywheel else {
        line(pages, &sw!(lang, "report.no_flywheel"));
        return;
    };
    let at = degrees(f.peak_torque_at_rad.to_degrees().rem_euclid(360.0));
    let rows = vec![
        vec![
            sw!(lang, "report.mean_torque"),
            si(f.mean_torque_n_m, "N·m"),
        ],
        vec![
            sw!(lang, "report.peak_torque", deg = at),
            si(f.peak_torque_n_m, "N·m"),
        ],
        vec![sw!(lang, "report.work_range"), si(f.work_range_j, "J")],
        vec![sw!(lang, "report.delta"), significant(REPORT_DELTA, 4)],
        vec![
            sw!(lang, "report.flywheel_inertia"),
            inertia(f.flywheel_kg_m2),
        ],
    ];
    table(pages, &[0.0, 420.0], &[], &rows);
}

/// §5: each cam's figures.
fn cams(pages: &mut Pages, r: &CourseReport, lang: Lang) {
    if r.cams.is_empty() {
        return;
    }
    pages.keep(6.0 * ROW);
    section(pages, &sw!(lang, "report.cams"));
    let mut rows = Vec::new();
    for c in &r.cams {
        let [angle, at] = c.largest_pressure;
        let at = degrees(at.to_degrees().rem_euclid(360.0));
        rows.push(vec![
            sw!(lang, "report.cam_base", name = c.name),
            si(c.base_radius_m, "m"),
        ]);
        rows.push(vec![
            sw!(lang, "report.cam_pressure", name = c.name, deg = at),
            degrees(angle.to_degrees()),
        ]);
        rows.push(vec![
            sw!(lang, "report.cam_limit", name = c.name),
            degrees(c.limit_rad.to_degrees()),
        ]);
        rows.push(vec![
            sw!(lang, "report.cam_radius", name = c.name),
            si(c.least_radius_m, "m"),
        ]);
    }
    table(pages, &[0.0, 420.0], &[], &rows);
}

/// §6: the results.
fn results(pages: &mut Pages, r: &CourseReport, lang: Lang) {
    pages.keep(10.0 * ROW);
    section(pages, &sw!(lang, "report.results"));
    let a = &r.analysis;
    let none = || sw!(lang, "report.none");
    let mut rows = vec![
        vec![sw!(lang, "report.r_dof"), r.mobility.dof.to_string()],
        vec![
            sw!(lang, "report.r_grashof"),
            a.grashof
                .as_ref()
                .map_or_else(none, |g| grashof(lang, g.class)),
        ],
        vec![
            sw!(lang, "report.r_k"),
            a.time_ratio.map_or_else(none, |k| significant(k, 4)),
        ],
    ];
    for (name, s) in &a.strokes_m {
        rows.push(vec![sw!(lang, "report.r_stroke", name = name), si(*s, "m")]);
    }
    for (name, s) in &a.swings_rad {
        rows.push(vec![
            sw!(lang, "report.r_swing", name = name),
            degrees(s.to_degrees()),
        ]);
    }
    if let Some(t) = &a.transmission_angle_rad {
        let at = degrees(t.at.to_degrees().rem_euclid(360.0));
        rows.push(vec![
            sw!(lang, "report.r_mu", deg = at),
            degrees(t.min.to_degrees()),
        ]);
    }
    if let (Some(fp), Some(first)) = (&r.course.forces, r.course.chosen.first()) {
        let label = sw!(lang, "report.r_balancing", n = first.number);
        rows.push(vec![label, si(fp.balancing_torque, "N·m")]);
    }
    if let Some(f) = &r.flywheel {
        rows.push(vec![
            sw!(lang, "report.flywheel_inertia"),
            inertia(f.flywheel_kg_m2),
        ]);
    }
    let head = [
        sw!(lang, "report.col_quantity"),
        sw!(lang, "report.col_value"),
    ];
    table(pages, &[0.0, 420.0], &head, &rows);
}

/// A Grashof class in the textbook's words.
fn grashof(lang: Lang, class: GrashofClass) -> String {
    match class {
        GrashofClass::CrankRocker => sw!(lang, "grashof.crank_rocker"),
        GrashofClass::DoubleCrank => sw!(lang, "grashof.double_crank"),
        GrashofClass::DoubleRocker => sw!(lang, "grashof.double_rocker"),
        GrashofClass::RockerCrank => sw!(lang, "grashof.rocker_crank"),
        GrashofClass::ChangePoint => sw!(lang, "grashof.change_point"),
        GrashofClass::TripleRocker => sw!(lang, "grashof.triple_rocker"),
    }
}

/// A moment of inertia, kg·m², in plain digits: a prefix would fall on the kilogram
/// (40.25 kkg·m²).
fn inertia(j: f64) -> String {
    format!("{} kg·m²", significant(j, 4))
}
