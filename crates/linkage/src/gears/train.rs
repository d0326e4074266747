//! A gear train's speeds: every member's angular speed from the inputs given, as a
//! linear system. A mesh of gears A and B whose axes are held by C (the frame or a
//! carrier) gives z_A (ω_A − ω_C) + σ z_B (ω_B − ω_C) = 0, σ = 1 for external teeth
//! (they turn opposite ways relative to C) and −1 for an internal mesh: fixed-axis,
//! planetary and differential trains alike (Willis' converted train). A belt or chain
//! stage gives ω_from = ± ratio · ω_to. The train's degrees of freedom are the members
//! less the rank of these rows; the inputs must be as many.

use nalgebra::{DMatrix, DVector};

use super::train_file::TrainFile;
pub use super::train_results::{
    AssemblyCheck, MemberSpeed, TrainError, TrainSolution, WillisRatio,
};

/// A train checked: its members by index, its constraint rows.
#[derive(Clone, Debug)]
pub struct Train {
    pub(super) file: TrainFile,
    /// The constraint rows over the members' speeds.
    pub(super) rows: Vec<Vec<f64>>,
    /// The members each row ties.
    pub(super) row_members: Vec<super::train_rows::RowMembers>,
}

impl Train {
    /// The train of `file`, its names and numbers checked.
    ///
    /// # Errors
    /// A name undefined or defined twice, a number outside its range, a mesh whose
    /// axes move apart or of two internal gears.
    pub fn new(file: TrainFile) -> Result<Self, TrainError> {
        super::train_rows::check_names(&file)?;
        let (rows, row_members) = super::train_rows::rows(&file)?;
        Ok(Self {
            file,
            rows,
            row_members,
        })
    }

    /// The degrees of freedom: the members less the rank of the meshes' and stages'
    /// rows.
    pub fn dof(&self) -> usize {
        self.file.members.len() - rank(&self.rows, self.file.members.len())
    }

    /// Every member's speed from the file's inputs.
    ///
    /// # Errors
    /// Inputs fewer or more than the degrees of freedom, or tied together.
    pub fn solve(&self) -> Result<TrainSolution, TrainError> {
        let inputs: Vec<(usize, f64)> = self
            .file
            .inputs
            .iter()
            .map(|i| (self.index(&i.member).unwrap_or(0), i.rpm))
            .collect();
        let dof = self.dof();
        if inputs.len() != dof {
            return Err(TrainError::Inputs {
                dof,
                given: inputs.len(),
            });
        }
        let speeds = self
            .speeds(&inputs)
            .map_err(|member| TrainError::InputsTied {
                member: self.file.members[member].name.clone(),
            })?;
        let speeds_rpm = self
            .file
            .members
            .iter()
            .zip(&speeds)
            .map(|(m, &rpm)| MemberSpeed {
                member: m.name.clone(),
                rpm,
            })
            .collect();
        Ok(TrainSolution {
            name: self.file.name.clone(),
            dof,
            speeds_rpm,
            willis: self.willis(),
            assembly: super::train_assembly::checks(&self.file),
        })
    }

    /// The members' speeds with `inputs` (member, speed) given; `Err(member)` where
    /// a member is left undetermined or the inputs contradict.
    fn speeds(&self, inputs: &[(usize, f64)]) -> Result<Vec<f64>, usize> {
        let n = self.file.members.len();
        let mut a = DMatrix::<f64>::zeros(self.rows.len() + inputs.len(), n);
        let mut b = DVector::<f64>::zeros(self.rows.len() + inputs.len());
        for (i, row) in self.rows.iter().enumerate() {
            for (j, &v) in row.iter().enumerate() {
                a[(i, j)] = v;
            }
        }
        for (k, &(member, value)) in inputs.iter().enumerate() {
            a[(self.rows.len() + k, member)] = 1.0;
            b[self.rows.len() + k] = value;
        }
        let svd = a.clone().svd(true, true);
        let scale = svd.singular_values.max().max(1.0);
        let tol = 1e-10 * scale;
        let rank = svd.singular_values.iter().filter(|&&s| s > tol).count();
        let x = svd.solve(&b, tol).map_err(|_| 0usize)?;
        let residual = (&a * &x - &b).norm();
        let size = b.norm().max(1.0);
        if rank < n || residual > 1e-9 * size {
            // The first input's member, or the first member, named.
            return Err(inputs.first().map_or(0, |i| i.0));
        }
        // The inputs as given, and the round-off of a member that stands still (a
        // ring braked by the gears, not by an input) as 0.
        let largest = x.amax();
        let mut speeds: Vec<f64> = x
            .iter()
            .map(|&v| if v.abs() <= 1e-12 * largest { 0.0 } else { v })
            .collect();
        for &(member, value) in inputs {
            speeds[member] = value;
        }
        Ok(speeds)
    }

    /// Every member's moment of inertia reduced to `to`: Σ J_i (ω_i / ω_to)², the
    /// inertia that stores the train's kinetic energy at `to`'s speed, kg·m²; `None`
    /// where `to` is not a member or stands still.
    pub fn reduced_inertia_kg_m2(&self, solution: &TrainSolution, to: &str) -> Option<f64> {
        let w_to = solution.speed_rpm(to).filter(|w| *w != 0.0)?;
        let energy: f64 = self
            .file
            .members
            .iter()
            .zip(&solution.speeds_rpm)
            .map(|(m, w)| m.inertia_kg_m2 * (w.rpm / w_to).powi(2))
            .sum();
        Some(energy)
    }

    /// A member's index by name.
    pub(super) fn index(&self, name: &str) -> Option<usize> {
        self.file.members.iter().position(|m| m.name == name)
    }

    /// Each carrier's central members' converted-train ratios, from the train with
    /// the carrier held and one central member turned once.
    fn willis(&self) -> Vec<WillisRatio> {
        let mut out = Vec::new();
        for (carrier, central) in super::train_rows::central_members(&self.file) {
            let Some(h) = self.index(&carrier) else {
                continue;
            };
            for (i, from) in central.iter().enumerate() {
                for to in &central[i + 1..] {
                    let (Some(a), Some(b)) = (self.index(from), self.index(to)) else {
                        continue;
                    };
                    let Ok(speeds) = self.speeds(&[(h, 0.0), (a, 1.0)]) else {
                        continue;
                    };
                    if speeds[b].abs() > 1e-12 {
                        out.push(WillisRatio {
                            carrier: carrier.clone(),
                            from: from.clone(),
                            to: to.clone(),
                            ratio: 1.0 / speeds[b],
                        });
                    }
                }
            }
        }
        out
    }
}

/// The rank of `rows` (each of `n` columns), by SVD.
fn rank(rows: &[Vec<f64>], n: usize) -> usize {
    if rows.is_empty() {
        return 0;
    }
    let a = DMatrix::from_fn(rows.len(), n, |i, j| rows[i][j]);
    let svd = a.svd(false, false);
    let tol = 1e-10 * svd.singular_values.max().max(1.0);
    svd.singular_values.iter().filter(|&&s| s > tol).count()
}
