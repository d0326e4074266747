//! The function tab's designs: a function generator through typed precision
//! points, or through Chebyshev points of a chosen function y = f(x) mapped onto
//! crank and rocker ranges, whose structural error over the range is plotted.

use linkage::synthesis::function::{
    FunctionFourBar, PrecisionPoint, chebyshev_spacing, error_curve, freudenstein, structural_error,
};

use linkage::synthesis::rows::read_rows;

use crate::synthesis::design::{Design, Figure, FunctionSpecError, SynthError, deg, mm, row};

/// A function to generate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Desired {
    /// y = log₁₀ x.
    Log10,
    /// y = x².
    Square,
    /// y = sin x (x in radians).
    Sine,
    /// y = eˣ.
    Exp,
    /// y = 1/x.
    Reciprocal,
}

impl Desired {
    /// Every function offered, in the menu's order.
    pub const ALL: [Desired; 5] = [
        Desired::Log10,
        Desired::Square,
        Desired::Sine,
        Desired::Exp,
        Desired::Reciprocal,
    ];

    /// Its name in the menu.
    pub fn label(self) -> &'static str {
        match self {
            Desired::Log10 => "y = log10 x",
            Desired::Square => "y = x²",
            Desired::Sine => "y = sin x",
            Desired::Exp => "y = exp x",
            Desired::Reciprocal => "y = 1/x",
        }
    }

    /// f(x); not finite outside its domain.
    pub fn at(self, x: f64) -> f64 {
        match self {
            Desired::Log10 => x.log10(),
            Desired::Square => x * x,
            Desired::Sine => x.sin(),
            Desired::Exp => x.exp(),
            Desired::Reciprocal => 1.0 / x,
        }
    }
}

/// A function mapped onto the linkage: x over its range turns the crank by the
/// input span from its start; y turns the rocker likewise.
#[derive(Clone, Debug, PartialEq)]
pub struct FunctionSpec {
    /// The function.
    pub f: Desired,
    /// x from, to.
    pub x_range: [f64; 2],
    /// Crank start and span, deg.
    pub input_deg: [f64; 2],
    /// Rocker start and span, deg.
    pub output_deg: [f64; 2],
    /// Number of precision points (Chebyshev spaced).
    pub points: usize,
}

impl Default for FunctionSpec {
    fn default() -> Self {
        Self {
            f: Desired::Log10,
            x_range: [1.0, 2.0],
            input_deg: [30.0, 60.0],
            output_deg: [240.0, 90.0],
            points: 3,
        }
    }
}

impl FunctionSpec {
    fn theta(&self, x: f64) -> f64 {
        let [x0, x1] = self.x_range;
        (self.input_deg[0] + self.input_deg[1] * (x - x0) / (x1 - x0)).to_radians()
    }

    /// The rocker angle the function asks for at crank angle `theta`, rad.
    fn phi_of_theta(&self, theta: f64) -> f64 {
        let [x0, x1] = self.x_range;
        let x = x0 + (theta.to_degrees() - self.input_deg[0]) / self.input_deg[1] * (x1 - x0);
        let (y0, y1) = (self.f.at(x0), self.f.at(x1));
        (self.output_deg[0] + self.output_deg[1] * (self.f.at(x) - y0) / (y1 - y0)).to_radians()
    }

    /// The precision points at the function's Chebyshev points.
    ///
    /// # Errors
    /// A range or span that is empty or not finite, a function not defined over
    /// the range or equal at its ends, or not 3 to 10 points.
    pub fn precision_points(&self) -> Result<Vec<PrecisionPoint>, FunctionSpecError> {
        let [x0, x1] = self.x_range;
        if !(3..=10).contains(&self.points) {
            return Err(FunctionSpecError::PointCount(self.points));
        }
        if !(x0.is_finite() && x1.is_finite() && x0 != x1) {
            return Err(FunctionSpecError::EmptyRange(x0, x1));
        }
        if self.input_deg[1] == 0.0 || self.output_deg[1] == 0.0 {
            return Err(FunctionSpecError::NoSpan);
        }
        let samples = (0..=100).map(|k| self.f.at(x0 + (x1 - x0) * f64::from(k) / 100.0));
        if samples.clone().any(|y| !y.is_finite()) {
            return Err(FunctionSpecError::Undefined {
                function: self.f.label().to_string(),
                x0,
                x1,
            });
        }
        if self.f.at(x0) == self.f.at(x1) {
            return Err(FunctionSpecError::EqualEnds(self.f.label().to_string()));
        }
        Ok(chebyshev_spacing(x0, x1, self.points)
            .into_iter()
            .map(|x| {
                let theta = self.theta(x);
                PrecisionPoint {
                    input_rad: theta,
                    output_rad: self.phi_of_theta(theta),
                }
            })
            .collect())
    }
}

/// The generator through typed points `input_deg, output_deg`.
pub fn from_points(text: &str, ground_mm: f64) -> Result<Design, SynthError> {
    let points: Vec<PrecisionPoint> = read_rows(text, 2)?
        .into_iter()
        .map(|v| PrecisionPoint {
            input_rad: v[0].to_radians(),
            output_rad: v[1].to_radians(),
        })
        .collect();
    let d = freudenstein(&points, ground_mm * 1e-3)?;
    Ok(Design {
        table: rows(&d, &points),
        scene: d.scene(points[0]),
        figure: Figure::None,
    })
}

/// The generator of `spec`, with its structural error over the range.
pub fn from_spec(spec: &FunctionSpec, ground_mm: f64) -> Result<Design, SynthError> {
    let points = spec.precision_points()?;
    let d = freudenstein(&points, ground_mm * 1e-3)?;
    let range = [spec.theta(spec.x_range[0]), spec.theta(spec.x_range[1])];
    let curve = error_curve(&d, points[0], range, |t| spec.phi_of_theta(t), 400);
    let largest = curve.iter().map(|e| e[1].abs()).fold(0.0, f64::max);
    let mut table = rows(&d, &points);
    table.push(row(
        "largest structural error over the range",
        if curve.len() == 401 {
            deg(largest)
        } else {
            format!("{} (the chain does not close over all of it)", deg(largest))
        },
    ));
    Ok(Design {
        table,
        scene: d.scene(points[0]),
        figure: Figure::ErrorCurve(
            curve
                .iter()
                .map(|e| [e[0].to_degrees(), e[1].to_degrees()])
                .collect(),
        ),
    })
}

fn rows(d: &FunctionFourBar, points: &[PrecisionPoint]) -> Vec<(String, String)> {
    let [k1, k2, k3] = d.k;
    let [a, b, c, g] = d.lengths;
    let error = structural_error(d, points)
        .map_or_else(|| "the chain does not close at a point".into(), deg);
    let method = if points.len() == 3 {
        "exact"
    } else {
        "least squares"
    };
    vec![
        row("method", format!("{method}, {} points", points.len())),
        row("K1, K2, K3", format!("{k1:.6}, {k2:.6}, {k3:.6}")),
        row("crank AB", mm(a.abs())),
        row("coupler BC", mm(b)),
        row("rocker CD", mm(c.abs())),
        row("ground AD", mm(g)),
        row("largest error at the points", error),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_log_generator_errs_by_its_structural_error_between_points() {
        let d = from_spec(&FunctionSpec::default(), 100.0).expect("designs");
        let Figure::ErrorCurve(curve) = d.figure else {
            panic!("no error curve");
        };
        let largest = curve.iter().map(|e| e[1].abs()).fold(0.0, f64::max);
        assert!(largest > 1e-4 && largest < 0.5, "{largest}°");
        let bad = FunctionSpec {
            x_range: [-1.0, 2.0],
            ..FunctionSpec::default()
        };
        assert!(matches!(
            from_spec(&bad, 100.0).expect_err("log of x ≤ 0"),
            SynthError::Function(FunctionSpecError::Undefined { .. })
        ));
    }
}
