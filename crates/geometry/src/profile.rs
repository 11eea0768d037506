//! Roller and raceway generatrix profiles (SPEC §1.4).
//!
//! A profile is the *drop* `z(x) ≥ 0`: the radial deviation inward from the nominal cylinder, as
//! a function of the axial coordinate `x` measured from the middle of the working length.
//! All lengths in metres.

/// A circular chamfer (edge break) at both ends of a profile (SPEC §1.4 item 2, flag F-10).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Chamfer {
    /// Axial length ΔF_x of the chamfer, measured inward from the roller end face.
    pub axial_length: f64,
    /// Radial height ΔF_z (used for mass properties; the arc below decides contact).
    pub radial_height: f64,
    /// Radius R_F of the arc, tangent to the generatrix at the chamfer start.
    pub radius: f64,
}

/// The families of SPEC §1.4.
#[derive(Debug, Clone, PartialEq)]
pub enum ProfileShape {
    /// Right circular cylinder: `z = 0` (sharp edges unless a chamfer is given).
    Straight,
    /// Straight central part of length `straight_length`, then a circular crown tangent to it
    /// reaching `drop` at the chamfer start `x_e` (SPEC §1.4 item 2, proposal F-10):
    /// `z = (|x| − L_c/2)² / (2 R_bo)`, `R_bo = (x_e − L_c/2)² / (2 P_bo)` unless given.
    Crowned {
        straight_length: f64,
        drop: f64,
        crown_radius: Option<f64>,
    },
    /// Logarithmic crown of seed 004 Table 1: `z = k ln(1 / (1 − c x²))` with `k` in metres and
    /// `c` in 1/m² (the seed prints k in mm and c in mm⁻²; flag F-11).
    Logarithmic { k: f64, c: f64 },
    /// Johns–Gohar logarithmic profile (Johns & Gohar 1981, standard form, not in the seeds):
    /// `z = 2Q/(π l E') · ln(1 / (1 − (1 − 0.3033 b/a)(2x/l)²))` for design load `Q`,
    /// effective length `l = 2a`, reduced modulus `E'` (SPEC eq. 1.13) and Hertz half-width `b`.
    JohnsGohar {
        design_load: f64,
        effective_length: f64,
        reduced_modulus: f64,
        hertz_half_width: f64,
    },
    /// Tabulated generatrix `(x, z)` with strictly increasing signed `x` (so worn profiles may be
    /// asymmetric), linear in between (SPEC §1.4 item 5). Outside the table the end values are held.
    Polyline { points: Vec<(f64, f64)> },
}

/// A complete profile: a family over the working length plus optional end chamfers.
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    pub shape: ProfileShape,
    pub chamfer: Option<Chamfer>,
    /// Half of the total length (roller length / 2, or raceway width / 2).
    pub half_length: f64,
}

impl Profile {
    /// A straight profile without chamfers.
    pub fn straight(half_length: f64) -> Self {
        Self {
            shape: ProfileShape::Straight,
            chamfer: None,
            half_length,
        }
    }

    /// Start of the chamfer `x_e` (end of the working length), measured from the middle.
    pub fn chamfer_start(&self) -> f64 {
        match self.chamfer {
            Some(c) => self.half_length - c.axial_length,
            None => self.half_length,
        }
    }

    /// Effective (working) contact length: the length over which the family applies.
    pub fn effective_length(&self) -> f64 {
        2.0 * self.chamfer_start()
    }

    /// Crown radius R_bo of a crowned profile, derived when not given (SPEC §1.4, F-10).
    pub fn crown_radius(&self) -> Option<f64> {
        match self.shape {
            ProfileShape::Crowned {
                straight_length,
                drop,
                crown_radius,
            } => crown_radius.or_else(|| {
                let run = self.chamfer_start() - 0.5 * straight_length;
                (drop > 0.0 && run > 0.0).then(|| run * run / (2.0 * drop))
            }),
            _ => None,
        }
    }

    /// Drop of the family alone at `|x| ≤ x_e` and its slope d z/d|x| (outward).
    fn family_drop(&self, x: f64) -> (f64, f64) {
        let ax = x.abs();
        match &self.shape {
            ProfileShape::Straight => (0.0, 0.0),
            ProfileShape::Crowned {
                straight_length, ..
            } => {
                let over = ax - 0.5 * straight_length;
                match self.crown_radius() {
                    Some(r) if over > 0.0 => (over * over / (2.0 * r), over / r),
                    _ => (0.0, 0.0),
                }
            }
            ProfileShape::Logarithmic { k, c } => log_drop(*k, *c, ax),
            ProfileShape::JohnsGohar {
                design_load,
                effective_length,
                reduced_modulus,
                hertz_half_width,
            } => {
                let l = *effective_length;
                let k = 2.0 * design_load / (std::f64::consts::PI * l * reduced_modulus);
                let c = (1.0 - 0.3033 * hertz_half_width / (0.5 * l)) * 4.0 / (l * l);
                log_drop(k, c, ax)
            }
            ProfileShape::Polyline { points } => {
                let (z, slope) = polyline_drop(points, x);
                (z, slope * x.signum())
            }
        }
    }

    /// Drop `z(x)` at axial position `x` (m from the middle). Beyond the ends the drop of the
    /// end point is returned; callers decide whether material exists there (`|x| ≤ half_length`).
    pub fn drop(&self, x: f64) -> f64 {
        let xe = self.chamfer_start();
        let x = x.clamp(-self.half_length, self.half_length);
        match self.chamfer {
            Some(chamfer) if x.abs() > xe => {
                let (ze, slope) = self.family_drop(xe.copysign(x));
                chamfer_drop(chamfer, xe, ze, slope, x.abs())
            }
            _ => self.family_drop(x).0,
        }
    }
}

/// `z = k ln(1/(1 − c x²))` and its slope, with the singularity at `c x² = 1` capped.
fn log_drop(k: f64, c: f64, ax: f64) -> (f64, f64) {
    let arg = (1.0 - c * ax * ax).max(1e-12);
    (-k * arg.ln(), 2.0 * k * c * ax / arg)
}

fn polyline_drop(points: &[(f64, f64)], x: f64) -> (f64, f64) {
    let Some(first) = points.first() else {
        return (0.0, 0.0);
    };
    let last = points[points.len() - 1];
    if x <= first.0 {
        return (first.1, 0.0);
    }
    if x >= last.0 {
        return (last.1, 0.0);
    }
    let k = points.partition_point(|p| p.0 <= x);
    let (x0, z0) = points[k - 1];
    let (x1, z1) = points[k];
    let slope = (z1 - z0) / (x1 - x0);
    (z0 + slope * (x - x0), slope)
}

/// Circular chamfer arc of radius R_F tangent to the generatrix (slope `slope`) at `(xe, ze)`;
/// vertical beyond the arc's quarter point (SPEC §1.4, proposal F-10 with the tangent at x_e).
fn chamfer_drop(chamfer: Chamfer, xe: f64, ze: f64, slope: f64, ax: f64) -> f64 {
    let theta = slope.atan();
    let r = chamfer.radius;
    let cx = xe - r * theta.sin();
    let cz = ze + r * theta.cos();
    let dx = ax - cx;
    if dx >= r {
        return cz.max(ze + chamfer.radial_height);
    }
    cz - (r * r - dx * dx).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn seed004(shape: ProfileShape) -> Profile {
        Profile {
            shape,
            chamfer: Some(Chamfer {
                axial_length: 0.5e-3,
                radial_height: 0.5e-3,
                radius: 0.6e-3,
            }),
            half_length: 3.75e-3,
        }
    }

    #[test]
    fn crown_radius_matches_spec_derived_values() {
        // SPEC §1.4: R_bo = 244.1 mm for P_bo = 3.2 µm and 120.2 mm for 6.5 µm.
        for (drop, expected) in [(3.2e-6, 0.2441), (6.5e-6, 0.1202)] {
            let p = seed004(ProfileShape::Crowned {
                straight_length: 4e-3,
                drop,
                crown_radius: None,
            });
            let r = p.crown_radius().unwrap();
            assert!((r - expected).abs() < 5e-5, "{r}");
            assert!((p.drop(3.25e-3) - drop).abs() < 1e-12);
            assert_eq!(p.drop(1.9e-3), 0.0);
        }
    }

    #[test]
    fn logarithmic_drops_match_spec_derived_values() {
        // SPEC §1.4 item 3: Z(x_e) = 2.05 / 10.3 µm, Z(2 mm) = 0.21 / 1.04 µm.
        let c = 0.093757e6;
        for (k, at_xe, at_2mm) in [
            (0.000443e-3, 2.05e-6, 0.21e-6),
            (0.002217e-3, 10.3e-6, 1.04e-6),
        ] {
            let p = seed004(ProfileShape::Logarithmic { k, c });
            assert!((p.drop(3.25e-3) - at_xe).abs() < 0.01e-6 * at_xe / 1e-6 + 0.01e-6);
            assert!((p.drop(-2e-3) - at_2mm).abs() < 0.01e-6);
        }
    }

    #[test]
    fn chamfer_is_continuous_and_grows() {
        let p = seed004(ProfileShape::Crowned {
            straight_length: 4e-3,
            drop: 3.2e-6,
            crown_radius: None,
        });
        let xe = 3.25e-3;
        assert!((p.drop(xe + 1e-9) - p.drop(xe - 1e-9)).abs() < 1e-10);
        assert!(p.drop(3.5e-3) > p.drop(3.3e-3));
        assert!(p.drop(3.75e-3) > 100e-6);
    }

    #[test]
    fn polyline_interpolates() {
        let p = Profile {
            shape: ProfileShape::Polyline {
                points: vec![(0.0, 0.0), (1e-3, 1e-6), (2e-3, 5e-6)],
            },
            chamfer: None,
            half_length: 2e-3,
        };
        assert!((p.drop(0.5e-3) - 0.5e-6).abs() < 1e-15);
        // Signed x: left of the first point the first drop is held (asymmetric wear allowed).
        assert_eq!(p.drop(-0.5e-3), 0.0);
        assert!((p.drop(1.5e-3) - 3e-6).abs() < 1e-15);
    }
}
