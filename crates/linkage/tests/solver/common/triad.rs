//! A crank driving a class-III Assur triad (a ternary link held by three binary
//! links, to the crank pin and to two ground pivots): a chain with no dyad
//! decomposition, solved by Newton alone.

use linkage::Vec2;

/// Geometry of the triad six-bar; the pins are placed at the crank angle 0.
#[derive(Clone, Copy, Debug)]
pub struct Triad {
    /// Crank length, m (pivot at the origin).
    pub crank: f64,
    /// Joint of the first binary link on the triad, at the start pose.
    pub q1: Vec2,
    /// The triad's other two joints, at the start pose.
    pub q2: Vec2,
    pub q3: Vec2,
    /// Ground pivots of the second and third binary links.
    pub g2: Vec2,
    pub g3: Vec2,
}

impl Triad {
    /// The layout of `newton_only_triad.rs`: it locks near +1 deg.
    pub fn locking() -> Self {
        let v = Vec2::new;
        Self {
            crank: 0.1,
            q1: v(0.3, 0.2),
            q2: v(0.5, 0.25),
            q3: v(0.4, 0.4),
            g2: v(0.6, 0.0),
            g3: v(0.2, 0.6),
        }
    }

    /// Crank pin at the start pose.
    pub fn p1(&self) -> Vec2 {
        Vec2::new(self.crank, 0.0)
    }

    /// Lengths of the three binary links (crank pin to Q1, G2 to Q2, G3 to Q3).
    pub fn lengths(&self) -> [f64; 3] {
        [
            (self.q1 - self.p1()).norm(),
            (self.q2 - self.g2).norm(),
            (self.q3 - self.g3).norm(),
        ]
    }

    /// The scene, with every guess off by `err` (m and rad), driven at 1.5 rad/s.
    pub fn scene(&self, err: f64) -> String {
        let bar = |a: Vec2, b: Vec2| (b - a).y.atan2((b - a).x).to_degrees();
        let [l1, l2, l3] = self.lengths();
        let (a1, a2, a3) = (
            bar(self.p1(), self.q1),
            bar(self.g2, self.q2),
            bar(self.g3, self.q3),
        );
        let (t2, t3) = (self.q2 - self.q1, self.q3 - self.q1);
        let (g2, g3, p1, q1, r) = (self.g2, self.g3, self.p1(), self.q1, self.crank);
        let (e, ed) = (err, err.to_degrees());
        format!(
            r#"Scene(name: "triad", models: Kinematics,
        links: [
            (name: "ground", ground: true, points: {{"O": (0.0, 0.0), "G2": ({}, {}), "G3": ({}, {})}}),
            (name: "crank", points: {{"O": (0.0, 0.0), "P1": ({r}, 0.0)}}),
            (name: "l1", points: {{"P1": (0.0, 0.0), "Q1": ({l1}, 0.0)}}),
            (name: "tri", points: {{"Q1": (0.0, 0.0), "Q2": ({}, {}), "Q3": ({}, {})}}),
            (name: "l2", points: {{"G2": (0.0, 0.0), "Q2": ({l2}, 0.0)}}),
            (name: "l3", points: {{"G3": (0.0, 0.0), "Q3": ({l3}, 0.0)}}),
        ],
        driver: (link: "crank", speed: RadPerSecond(1.5), start: 0.0),
        guess: {{
            "crank": (0.0, 0.0, 0.0),
            "l1": ({}, {}, {a1}),
            "tri": ({}, {}, {ed}),
            "l2": ({}, {}, {}),
            "l3": ({}, {}, {}),
        }})"#,
            g2.x,
            g2.y,
            g3.x,
            g3.y,
            t2.x,
            t2.y,
            t3.x,
            t3.y,
            p1.x + e,
            p1.y - e,
            q1.x - e,
            q1.y + e,
            g2.x,
            g2.y,
            a2 + ed,
            g3.x,
            g3.y,
            a3 - ed,
        )
    }
}
