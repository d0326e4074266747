//! A cam over its turn as a table, the same for `linkage cam`'s CSV and JSON and for
//! the app's export: the follower's motion at the cam's speed and the cam's points
//! and figures, one row per cam angle, in SI (an arm's lift in radians).

use super::disc::CamPoint;

/// The columns.
pub const CAM_TABLE_HEADER: [&str; 12] = [
    "angle_deg",
    "s",
    "v",
    "a",
    "jerk",
    "pitch_x_m",
    "pitch_y_m",
    "profile_x_m",
    "profile_y_m",
    "pressure_angle_deg",
    "pitch_radius_m",
    "profile_radius_m",
];

/// The row of `p` at a cam speed of `speed_rad_s`.
pub fn cam_table_row(p: &CamPoint, speed_rad_s: f64) -> [f64; 12] {
    let w = speed_rad_s;
    let m = &p.motion;
    [
        p.angle_rad.to_degrees(),
        m.s,
        m.v * w,
        m.a * w * w,
        m.j * w * w * w,
        p.pitch_m[0],
        p.pitch_m[1],
        p.profile_m[0],
        p.profile_m[1],
        p.pressure_angle_rad.to_degrees(),
        p.pitch_radius_m,
        p.profile_radius_m,
    ]
}
