//! The plot pane (egui_plot): output motion and transmission angle against the crank
//! angle, input torque and force amplification, and for dynamic scenes the run
//! (ω–φ, ω–t, φ–t) and the reduced model J(q), M(q); each with a cursor at the
//! current position.

use eframe::egui;
use egui_plot::{Line, PlotPoints, VLine};
use linkage::scene::Models;
use linkage_diagram::numbers::Prefix;

use crate::i18n::tr;
use crate::session::Session;
use crate::session::curves::ModelCurves;
use crate::session::derived::Shown;
use crate::state::AppState;
use crate::ui::control_map::ControlKind;
use crate::ui::plot_axes::{self, Axis, AxisWord, CRANK, Unit};

/// Which plot the plot pane shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlotTab {
    /// Output displacement, velocity and acceleration against crank angle.
    Output,
    /// Transmission angle against crank angle.
    Transmission,
    /// Every output against the main shaft, with its dwells.
    Timing,
    /// A cam's follower: lift, velocity, acceleration and jerk against the cam angle.
    CamMotion,
    /// A cam's pressure angle and radius of curvature against their limits.
    CamLimits,
    /// Input torque and force amplification (kinetostatic scenes).
    Torque,
    /// The flywheel by the energy method (kinetostatic scenes).
    Flywheel,
    /// The real speed through the cycle with the scene's drive.
    Steady,
    /// The shaking force on the frame (kinetostatic scenes).
    Shaking,
    /// omega-phi, omega-t and phi-t of the dynamic run.
    Motion,
    /// J(q) and M(q) (dynamic scenes).
    ReducedModel,
}

/// Whether `tab` has anything to show for `s` (a slider appears only where its
/// parameter exists; so does a plot).
pub fn tab_available(tab: PlotTab, s: &Session) -> bool {
    let c = s.curves();
    match tab {
        PlotTab::Output => !c.outputs.is_empty(),
        PlotTab::Transmission => !c.transmission_deg.is_empty(),
        PlotTab::Timing => !c.timing.lanes.is_empty(),
        PlotTab::CamMotion | PlotTab::CamLimits => crate::ui::cam_plots::has_cams(s),
        // What the scene models: its curves are computed only when the tab is shown.
        PlotTab::Torque | PlotTab::Flywheel | PlotTab::Shaking => {
            s.models() == Models::Kinetostatics
        }
        PlotTab::Steady => s.models() != Models::Kinematics && s.mechanism().drive.is_some(),
        PlotTab::Motion => matches!(s.dynamics(), Some(Ok(_))),
        PlotTab::ReducedModel => s.models() == Models::Dynamics,
    }
}

/// Input angle of the current pose on the curves' (unwrapped) axis, deg.
fn cursor_deg(s: &Session) -> f64 {
    let c = s.curves();
    let now = s.input_rad().to_degrees();
    match c.input_deg.first() {
        Some(&first) if c.full_rotation => first + (now - first).rem_euclid(360.0),
        _ => now,
    }
}

/// A tab's short name and its full name in the app's language.
fn tab_words(tab: PlotTab) -> (String, String) {
    match tab {
        PlotTab::Output => (tr!("plot.output"), tr!("plot.output_hint")),
        PlotTab::Transmission => (tr!("plot.transmission"), tr!("plot.transmission_hint")),
        PlotTab::Timing => (tr!("plot.timing"), tr!("plot.timing_hint")),
        PlotTab::CamMotion => (tr!("plot.cam_motion"), tr!("plot.cam_motion_hint")),
        PlotTab::CamLimits => (tr!("plot.cam_limits"), tr!("plot.cam_limits_hint")),
        PlotTab::Torque => (tr!("plot.torque"), tr!("plot.torque_hint")),
        PlotTab::Flywheel => (tr!("plot.flywheel"), tr!("plot.flywheel_hint")),
        PlotTab::Steady => (tr!("plot.speed"), tr!("plot.speed_hint")),
        PlotTab::Shaking => (tr!("plot.shaking"), tr!("plot.shaking_hint")),
        PlotTab::Motion => (tr!("plot.motion"), tr!("plot.motion_hint")),
        PlotTab::ReducedModel => (tr!("plot.reduced"), tr!("plot.reduced_hint")),
    }
}

/// The tabs: the plot, its short name (so that a phone's sheet holds the row) and
/// its full name, shown on hover.
const TABS: [(PlotTab, &str, &str); 11] = [
    (PlotTab::Output, "Output", "the output's s, v, a"),
    (PlotTab::Transmission, "Transmission", "transmission angle"),
    (
        PlotTab::Timing,
        "Timing",
        "timing diagram: every output against the main shaft, dwells shaded",
    ),
    (
        PlotTab::CamMotion,
        "Cam s v a j",
        "the cam's follower: lift, velocity, acceleration, jerk",
    ),
    (
        PlotTab::CamLimits,
        "Cam limits",
        "the cam's pressure angle and radius of curvature against their limits",
    ),
    (
        PlotTab::Torque,
        "Torque",
        "input torque, and the force amplification (log10 of N per N·m)",
    ),
    (
        PlotTab::Flywheel,
        "Flywheel",
        "flywheel by the energy method",
    ),
    (
        PlotTab::Steady,
        "Speed",
        "the real speed with the drive: steady state and run-up",
    ),
    (
        PlotTab::Shaking,
        "Shaking",
        "shaking force, with the crank counterweight",
    ),
    (PlotTab::Motion, "ω–φ, ω–t, φ–t", "the dynamic run"),
    (PlotTab::ReducedModel, "J(q), M(q)", "the reduced model"),
];

/// The plot pane's own state: the tab shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PlotsPanel {
    /// The plot shown.
    pub tab: PlotTab,
}

impl Default for PlotsPanel {
    fn default() -> Self {
        Self {
            tab: PlotTab::Output,
        }
    }
}

impl PlotsPanel {
    /// The plot pane.
    pub fn ui(&mut self, ui: &mut egui::Ui, st: &mut AppState) {
        // A scene without the shown plot (a new scene, a changed model) shows the output.
        if !tab_available(self.tab, &st.session) {
            self.tab = PlotTab::Output;
        }
        self.tab_row(ui, st);
        // The plots scroll inside the pane below the tab row, which stays in view:
        // however many plots a tab holds, the pane keeps its size.
        egui::ScrollArea::both()
            .id_salt("plots")
            .auto_shrink(false)
            .show(ui, |ui| self.tab_body(ui, &st.session));
    }

    /// The row of tabs: short names, so that a phone's sheet holds it; the full name
    /// on hover. Each tab is noted where it is drawn (tests check it stays in view).
    fn tab_row(&mut self, ui: &mut egui::Ui, st: &mut AppState) {
        ui.horizontal_wrapped(|ui| {
            // The control map keeps the English names: the tests' handles in any
            // language.
            for (tab, id, _) in TABS {
                if tab_available(tab, &st.session) {
                    let (label, full) = tab_words(tab);
                    let r = ui
                        .selectable_value(&mut self.tab, tab, label)
                        .on_hover_text(full);
                    st.controls.note(ui, ControlKind::PlotTab, id, &r);
                }
            }
        });
    }

    /// The shown tab's plots.
    fn tab_body(&self, ui: &mut egui::Ui, s: &Session) {
        match self.tab {
            PlotTab::Output => output_plots(ui, s),
            PlotTab::Transmission => {
                let x = cursor_deg(s);
                let angle = Axis::word(AxisWord::TransmissionAngle, Unit::Degrees);
                let data = &s.curves().transmission_deg;
                row(
                    ui,
                    "transmission",
                    plot_key(s),
                    &[(angle, CRANK, data, Some(x))],
                );
            }
            PlotTab::Timing => {
                crate::ui::plot_layout::side_by_side(ui, 1, |ui, _, height| {
                    crate::ui::timing_plot::timing_plot(ui, s, cursor_deg(s), height);
                });
            }
            PlotTab::CamMotion => crate::ui::cam_plots::motion_plots(ui, s),
            PlotTab::CamLimits => crate::ui::cam_plots::limit_plots(ui, s),
            PlotTab::Torque => torque_plots(ui, s),
            PlotTab::Flywheel => flywheel_tab(ui, s),
            PlotTab::Steady => steady_tab(ui, s),
            PlotTab::Shaking => shaking_tab(ui, s),
            PlotTab::Motion => motion_plots(ui, s),
            PlotTab::ReducedModel => reduced_model_plots(ui, s),
        }
    }
}

/// What names a plot's curves: the scene and its generation.
fn plot_key(s: &Session) -> (&str, u64) {
    (s.scene().name.as_str(), s.generation())
}

/// The main output's displacement, rate and acceleration against the crank angle.
fn output_plots(ui: &mut egui::Ui, s: &Session) {
    let c = s.curves();
    // The scene's main output first: that is the one the papers plot.
    let main = &s.mechanism().links[s.mechanism().output].name;
    let Some(out) = c
        .outputs
        .iter()
        .find(|o| &o.name == main)
        .or(c.outputs.first())
    else {
        return;
    };
    // An angle in degrees; a slider's travel, speed and acceleration in the scene's
    // own length unit (a mm scene plots mm, mm/s and mm/s²), as its lengths are.
    // Short titles, the textbook's symbols: a low plot holds them whole.
    let unit = s.scene().length_unit;
    let per_m = 1.0 / unit.to_metres();
    let scaled: Vec<Vec<[f64; 2]>>;
    let (data, units, symbols) = if out.is_angle {
        (
            [
                out.value.as_slice(),
                out.rate.as_slice(),
                out.acceleration.as_slice(),
            ],
            [Unit::Degrees, Unit::Fixed("°/s"), Unit::Fixed("°/s²")],
            ["θ", "ω", "α"],
        )
    } else {
        scaled = [&out.value, &out.rate, &out.acceleration]
            .iter()
            .map(|d| d.iter().map(|&[x, y]| [x, y * per_m]).collect())
            .collect();
        let units = match unit {
            linkage::scene::LengthUnit::Millimetre => ["mm", "mm/s", "mm/s²"],
            linkage::scene::LengthUnit::Metre => ["m", "m/s", "m/s²"],
        }
        .map(Unit::Fixed);
        (
            [
                scaled[0].as_slice(),
                scaled[1].as_slice(),
                scaled[2].as_slice(),
            ],
            units,
            ["s", "v", "a"],
        )
    };
    let names: Vec<String> = symbols
        .iter()
        .map(|q| format!("{} {q}", out.name))
        .collect();
    let x = cursor_deg(s);
    let specs: Vec<PlotSpec<'_>> = (0..3)
        .map(|i| (Axis::new(&names[i], units[i]), CRANK, data[i], Some(x)))
        .collect();
    row(ui, "output", plot_key(s), &specs);
}

/// The input torque's axis.
const TORQUE: Axis<'static> = Axis::word(AxisWord::InputTorque, Unit::Si("N·m"));
/// The force amplification's axis: the logarithm of the output's force per unit input
/// torque (N per N·m; the tab's hover says so).
const AMPLIFICATION: Axis<'static> = Axis::word(AxisWord::Amplification, Unit::None);

/// The input torque and the force amplification (on a log scale).
fn torque_plots(ui: &mut egui::Ui, s: &Session) {
    let Some(c) = model_curves(ui, s) else {
        return;
    };
    let log_amp: Vec<[f64; 2]> = c
        .amplification
        .iter()
        .filter(|p| p[1] > 0.0)
        .map(|p| [p[0], p[1].log10()])
        .collect();
    let x = cursor_deg(s);
    row(
        ui,
        "torque",
        plot_key(s),
        &[
            (TORQUE, CRANK, &c.torque_n_m, Some(x)),
            (AMPLIFICATION, CRANK, &log_amp, Some(x)),
        ],
    );
}

/// The flywheel tab: its plots, or why the scene has no flywheel to size.
fn flywheel_tab(ui: &mut egui::Ui, s: &Session) {
    let Some(c) = model_curves(ui, s) else {
        return;
    };
    match &c.flywheel {
        Some(Ok(sized)) => {
            crate::ui::flywheel_plots::flywheel_plots(ui, plot_key(s), sized, cursor_deg(s))
        }
        Some(Err(why)) => {
            let why = crate::ui::words::refusal(why, s.scene().length_unit);
            ui.label(tr!("plot.no_flywheel", why = why));
        }
        None => {}
    }
}

/// The steady-state tab: its plots, or why the scene has none.
fn steady_tab(ui: &mut egui::Ui, s: &Session) {
    let Some(c) = model_curves(ui, s) else {
        return;
    };
    match &c.steady {
        Some(Ok(st)) => {
            let nominal = s.mechanism().driver.speed_rad_s;
            let run_up = c.run_up.as_ref().and_then(|r| r.as_ref().ok());
            crate::ui::machine_plots::steady_plots(
                ui,
                plot_key(s),
                st,
                run_up.map(Vec::as_slice),
                nominal,
                cursor_deg(s),
            );
        }
        Some(Err(why)) => {
            let why = crate::ui::words::refusal(why, s.scene().length_unit);
            ui.label(tr!("plot.no_steady", why = why));
        }
        None => {}
    }
}

/// The shaking-force tab: its plots, or why the scene has none.
fn shaking_tab(ui: &mut egui::Ui, s: &Session) {
    let Some(c) = model_curves(ui, s) else {
        return;
    };
    match &c.shaking {
        Some(Ok(sc)) => {
            crate::ui::machine_plots::shaking_plots(ui, plot_key(s), sc, cursor_deg(s));
        }
        Some(Err(why)) => {
            let why = crate::ui::words::refusal(why, s.scene().length_unit);
            ui.label(tr!("plot.no_shaking", why = why));
        }
        None => {}
    }
}

/// The dynamic run: ω against φ and t, φ against t.
fn motion_plots(ui: &mut egui::Ui, s: &Session) {
    let Some(Ok(run)) = s.dynamics() else {
        return;
    };
    let t = s.time_s();
    let omega = Axis::new("ω", Unit::Fixed("rad/s"));
    let phi = Axis::new("φ", Unit::Degrees);
    let time = Axis::new("t", Unit::Fixed("s"));
    let now = Some(s.input_rad().to_degrees());
    row(
        ui,
        "motion",
        plot_key(s),
        &[
            (omega, phi, &run.omega_phi, now),
            (omega, time, &run.omega_t, Some(t)),
            (phi, time, &run.phi_t, Some(t)),
        ],
    );
}

/// The reduced inertia J(q) and moment M(q).
fn reduced_model_plots(ui: &mut egui::Ui, s: &Session) {
    let Some(c) = model_curves(ui, s) else {
        return;
    };
    let x = cursor_deg(s);
    let q = Axis::new("q", Unit::Degrees);
    let inertia = Axis::new("J(q)", Unit::Fixed("kg·m²"));
    let moment = Axis::word(AxisWord::ReducedTorqueAtRest, Unit::Si("N·m"));
    row(
        ui,
        "reduced",
        plot_key(s),
        &[
            (inertia, q, &c.inertia_kg_m2, Some(x)),
            (moment, q, &c.moment_n_m, Some(x)),
        ],
    );
}

/// The model curves to plot: the current ones, or while edits come (a slider being
/// dragged) those from before them, until a frame without an edit makes the new ones.
fn model_curves<'s>(ui: &mut egui::Ui, s: &'s Session) -> Option<&'s ModelCurves> {
    match s.model_curves_shown() {
        Shown::Current(c) | Shown::Outdated(c) => Some(c),
        Shown::Pending => {
            ui.weak(tr!("plot.computing"));
            None
        }
    }
}

/// One plot of a row: (y axis, x axis, data, cursor position on x).
type PlotSpec<'a> = (Axis<'a>, Axis<'a>, &'a [[f64; 2]], Option<f64>);

/// Plots side by side where the pane is wide enough, else one under another.
fn row(ui: &mut egui::Ui, id: &str, generation: (&str, u64), plots: &[PlotSpec<'_>]) {
    crate::ui::plot_layout::side_by_side(ui, plots.len(), |ui, i, height| {
        plot(ui, (id, i, generation), &plots[i], height);
    });
}

/// One plot, `height` high, keyed by `key` (the mechanism's, so that an edit re-fits
/// its bounds), its y values in the unit and prefix that suit them.
fn plot(
    ui: &mut egui::Ui,
    key: (&str, usize, (&str, u64)),
    (y, x, data, cursor): &PlotSpec<'_>,
    height: f32,
) {
    let series = plot_axes::series(*y, data);
    let [lo, hi] = crate::ui::plot_layout::robust_range(&series.points);
    let x_title = plot_axes::title(*x, Prefix::NONE);
    plot_axes::plot(key, height, &x_title, &series.title)
        .default_y_bounds(lo, hi)
        .show(ui, |p| {
            p.line(Line::new(
                series.title.text.clone(),
                PlotPoints::from(series.points),
            ));
            if let Some(x) = cursor.filter(|x| x.is_finite()) {
                p.vline(VLine::new(tr!("plot.now"), x));
            }
        });
}
