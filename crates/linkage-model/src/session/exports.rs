//! What the session writes for the user: the sweep as CSV and the sheet of the
//! current position as A4 pages of SVG, and a cam joint as CSV and its profile as SVG.

use linkage_diagram::cycle_table::{CycleTable, DEFAULT_STEP_DEG};
use linkage_diagram::words::Lang;

use super::Session;

impl Session {
    /// The current mechanism's cycle as CSV a student pastes into a report, as
    /// `linkage sweep` writes it: the input on whole degrees, lengths in the scene's
    /// unit, columns named with units, velocities at the scene's crank speed.
    ///
    /// # Errors
    /// The sweep's error.
    pub fn sweep_csv(&self) -> Result<String, linkage::LinkageError> {
        let mut k = self.kinematics().clone();
        CycleTable::new(self.scene().length_unit).csv(&mut k, DEFAULT_STEP_DEG)
    }

    /// The sheet of the current position (pose, polygons, tables; instant centres if
    /// `centres`; the force polygons where the scene has them) as A4 pages of SVG:
    /// what `linkage diagram` writes for the same scene and input.
    pub fn sheet(&self, centres: bool, lang: Lang) -> linkage_diagram::pages::Sheet {
        let m = self.mechanism();
        let pose = self.pose();
        let found = linkage::instant_centres::instant_centres(m, pose);
        let position = linkage_diagram::svg::Position {
            mechanism: m,
            solution: pose,
            equations: self.polygons(),
            centres: Some(&found),
            forces: self.force_polygons().and_then(|r| r.as_ref().ok()),
        };
        let parts = linkage_diagram::svg::Parts {
            centres,
            forces: true,
            ..Default::default()
        };
        linkage_diagram::svg::sheet(&position, parts, lang)
    }
}

impl Session {
    /// Cam joint `index` over its turn as CSV, in the `linkage cam` format (SI, an
    /// arm's lift in radians, rates at the cam's speed); `None` without that joint.
    pub fn cam_csv(&self, index: usize) -> Option<String> {
        use linkage::cam::{CAM_TABLE_HEADER, cam_table_row};
        let c = self.curves().cams.get(index)?;
        let mut out = CAM_TABLE_HEADER.join(",");
        out.push('\n');
        for p in &c.points {
            let row: Vec<String> = cam_table_row(p, c.speed_rad_s)
                .iter()
                .map(f64::to_string)
                .collect();
            out.push_str(&row.join(","));
            out.push('\n');
        }
        Some(out)
    }

    /// Cam joint `index`'s profile sheet as SVG (as `linkage cam --svg` draws one);
    /// `None` without that joint.
    pub fn cam_svg(&self, index: usize, lang: Lang) -> Option<String> {
        let c = self.curves().cams.get(index)?;
        let m = self.mechanism();
        let joint = m.cams.get(index)?;
        // The links by the names the user gave them, not the joint's own id
        // ("crank/bell_crank").
        let title = linkage_diagram::words::cam_joint_title(
            lang,
            &m.name,
            &m.links[joint.cam].name,
            &m.links[joint.follower].name,
        );
        let sheet = linkage_diagram::svg_cam::cam_sheet(
            &linkage_diagram::svg_cam::CamSheet {
                title: &title,
                points: &c.points,
                base_radius_m: c.base_radius_m,
                pressure_limit_rad: c.pressure_limit_rad,
            },
            lang,
        );
        // One page: the profile fits A4 by construction.
        Some(sheet.first_page().to_owned())
    }
}

impl Session {
    /// The course sheet of the current mechanism in `lang`: `course.positions`
    /// positions from its first (the start of the crank's range unless given),
    /// polygons at the positions numbered `course.chosen` (and the force polygons at
    /// the first where the scene has force data), on A4 pages, as `linkage
    /// course-sheet` draws it.
    ///
    /// # Errors
    /// Fewer than 2 positions, a chosen number past the last position, or a position
    /// that does not solve.
    pub fn course_sheet(
        &self,
        course: &CourseChoice,
        lang: Lang,
    ) -> Result<linkage_diagram::pages::Sheet, linkage::LinkageError> {
        let mut k = self.kinematics().clone();
        let sheet = linkage_diagram::course::CourseSheet::compute_from(
            &mut k,
            course.positions,
            course.first_deg,
            &course.chosen,
        )?;
        Ok(linkage_diagram::svg_course::course_sheet(&sheet, lang))
    }
}

impl Session {
    /// The course-design report of the current mechanism in `lang`, with the course
    /// sheet's positions of `course`, as `linkage course-report` writes it.
    ///
    /// # Errors
    /// What the course sheet and the cycle's analysis refuse.
    pub fn course_report(
        &self,
        course: &CourseChoice,
        lang: Lang,
    ) -> Result<linkage_diagram::pages::Sheet, linkage::LinkageError> {
        let mut k = self.kinematics().clone();
        let data = linkage_diagram::course_report::CourseReport::compute_from(
            &mut k,
            course.positions,
            course.first_deg,
            &course.chosen,
        )?;
        Ok(linkage_diagram::svg_report::course_report(&data, lang))
    }
}

/// What a course sheet or report is asked for: how many positions, from which crank
/// angle, and the positions drawn with their polygons.
#[derive(Clone, Debug, PartialEq)]
pub struct CourseChoice {
    /// Positions over the crank's range.
    pub positions: usize,
    /// The crank angle of position 0, degrees; the start of the range if `None`.
    pub first_deg: Option<f64>,
    /// The positions drawn with their polygons.
    pub chosen: Vec<usize>,
}
