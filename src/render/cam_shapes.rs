//! A cam joint as drawn: the cam's disc turning with its link (a fan of triangles
//! from its centre, so that the whole profile is filled, and its outline) and the
//! follower's roller on it. The rim is red where the cam passes a limit.

use glam::Vec2;

use super::drawn::{Drawn, colour};
use super::shape::{Kind, Shape};

/// The cams' discs, drawn under the links.
pub(super) fn cam_discs(push: &mut impl FnMut(Option<Shape>), d: &Drawn<'_>) {
    let (m, pose) = (d.s.mechanism(), d.s.pose());
    let topology = d.s.topology();
    for ((cam, profile), past) in m
        .cams
        .iter()
        .zip(&topology.cam_profiles)
        .zip(&topology.cam_past_limit)
    {
        let link = &pose.links[cam.cam];
        let on_screen: Vec<Vec2> = profile
            .iter()
            .map(|p| {
                let w = link.world(p);
                d.cam.local([w.x, w.y])
            })
            .collect();
        let centre = d.cam.local([cam.centre.x, cam.centre.y]);
        for (i, &a) in on_screen.iter().enumerate() {
            let b = on_screen[(i + 1) % on_screen.len()];
            // Grown by a little, so that neighbours overlap and their antialiased
            // edges leave no seams; the outline covers the growth at the rim.
            push(Shape::new(
                Kind::Fill,
                [centre, a, b],
                0.1 * d.bar,
                colour::CAM,
                [0.0; 2],
            ));
            // The rim in red where the cam passes a limit (pressure angle, undercut).
            let (edge, width) = match past.get(i) {
                Some(true) => (colour::PAST_LIMIT, 0.6 * d.bar),
                _ => (colour::CAM_EDGE, 0.25 * d.bar),
            };
            push(Shape::new(Kind::Line, [a, b, a], width, edge, [0.0; 2]));
        }
    }
}

/// The followers' rollers, drawn over the links.
pub(super) fn rollers(push: &mut impl FnMut(Option<Shape>), d: &Drawn<'_>) {
    for cam in &d.s.mechanism().cams {
        let c = d.pos(cam.roller);
        let radius = cam.roller_radius_m as f32;
        push(Shape::new(
            Kind::Pin,
            [c, c, c],
            radius,
            colour::ROLLER,
            [0.0; 2],
        ));
    }
}
