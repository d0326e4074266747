//! Points and axis-aligned rectangles in pane pixels (y down), the little geometry
//! the layout needs: a full vector library would add nothing here.

/// A point or vector, pixels or figure units.
pub type Pt = [f64; 2];

/// An axis-aligned rectangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rect {
    /// Left, top corner.
    pub min: Pt,
    /// Right, bottom corner.
    pub max: Pt,
}

impl Rect {
    /// The rectangle of width `w`, height `h` with its left top corner at `min`.
    pub fn from_min_size(min: Pt, w: f64, h: f64) -> Self {
        Self {
            min,
            max: [min[0] + w, min[1] + h],
        }
    }

    /// The smallest rectangle holding every point (`None` for none).
    pub fn around(points: impl IntoIterator<Item = Pt>) -> Option<Self> {
        points.into_iter().fold(None, |r, p| {
            Some(match r {
                None => Self { min: p, max: p },
                Some(r) => Self {
                    min: [r.min[0].min(p[0]), r.min[1].min(p[1])],
                    max: [r.max[0].max(p[0]), r.max[1].max(p[1])],
                },
            })
        })
    }

    /// Width.
    pub fn width(&self) -> f64 {
        self.max[0] - self.min[0]
    }

    /// Height.
    pub fn height(&self) -> f64 {
        self.max[1] - self.min[1]
    }

    /// Centre.
    pub fn centre(&self) -> Pt {
        [
            0.5 * (self.min[0] + self.max[0]),
            0.5 * (self.min[1] + self.max[1]),
        ]
    }

    /// Grown by `d` on every side (shrunk for negative `d`).
    pub fn expand(&self, d: f64) -> Self {
        Self {
            min: [self.min[0] - d, self.min[1] - d],
            max: [self.max[0] + d, self.max[1] + d],
        }
    }

    /// Whether the two overlap with positive area.
    pub fn overlaps(&self, o: &Rect) -> bool {
        self.min[0] < o.max[0]
            && o.min[0] < self.max[0]
            && self.min[1] < o.max[1]
            && o.min[1] < self.max[1]
    }

    /// Whether `o` lies wholly inside.
    pub fn contains_rect(&self, o: &Rect) -> bool {
        o.min[0] >= self.min[0]
            && o.min[1] >= self.min[1]
            && o.max[0] <= self.max[0]
            && o.max[1] <= self.max[1]
    }

    /// Whether the segment `a`–`b` passes through the rectangle (Liang–Barsky clip).
    pub fn crosses_segment(&self, a: Pt, b: Pt) -> bool {
        let d = [b[0] - a[0], b[1] - a[1]];
        let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
        for (p, q) in [
            (-d[0], a[0] - self.min[0]),
            (d[0], self.max[0] - a[0]),
            (-d[1], a[1] - self.min[1]),
            (d[1], self.max[1] - a[1]),
        ] {
            if p == 0.0 {
                if q < 0.0 {
                    return false;
                }
            } else {
                let t = q / p;
                if p < 0.0 {
                    t0 = t0.max(t);
                } else {
                    t1 = t1.min(t);
                }
                if t0 > t1 {
                    return false;
                }
            }
        }
        true
    }
}

/// `a` + `s`·`d`.
pub fn along(a: Pt, d: Pt, s: f64) -> Pt {
    [a[0] + s * d[0], a[1] + s * d[1]]
}

/// Distance between two points.
pub fn distance(a: Pt, b: Pt) -> f64 {
    (b[0] - a[0]).hypot(b[1] - a[1])
}
