//! Cage ↔ guiding-land contact as a narrow journal bearing (SPEC §5.5; seed 001 cites
//! Zhilnikov & Samsonov without formulas, ⚠ F-43).
//!
//! The model sits behind the small trait [`QuasiStaticLandModel`] so that a finite journal-bearing
//! solver (the Reynolds crate, SPEC §8.6) can replace the default [`ShortBearing`] later.

use rolldyn_contact::damping::TwoLevelFriction;
use rolldyn_reynolds::cage_land::couette_land_torque;
use std::f64::consts::PI;

/// Inputs of a cage–land evaluation (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CageLandInput {
    /// Radius of the land film (centring surface), m.
    pub land_radius_m: f64,
    /// Axial width of one rail, m.
    pub rail_width_m: f64,
    /// Number of rails (independent short bearings side by side).
    pub rails: u32,
    /// Radial clearance c = g_пп/2 of the concentric cage, m.
    pub radial_clearance_m: f64,
    /// Oil viscosity in the film, Pa·s.
    pub viscosity_pa_s: f64,
    /// Cage angular speed ω₀, rad/s.
    pub cage_speed_rad_s: f64,
    /// Angular speed of the ring carrying the land, rad/s.
    pub land_speed_rad_s: f64,
    /// Angular speed of the load direction, rad/s (0: the resultant of the roller forces is
    /// fixed in space, as with a stationary radial load).
    pub load_speed_rad_s: f64,
    /// Magnitude of the resultant of the roller–bar forces √(F_SB² + F_SГ²), N.
    pub roller_force_n: f64,
    /// Cage mass, kg (centrifugal force of the displaced cage F_cs = m e ω₀²).
    pub cage_mass_kg: f64,
}

/// Outputs of a cage–land evaluation.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CageLandOutput {
    /// Friction moment on the cage about the bearing axis (signed, along +e_z), N·m.
    pub torque_on_cage_n_m: f64,
    /// Pressing force F_RS = F_cs + √(F_SB² + F_SГ²) (SPEC §5.5), N.
    pub pressing_force_n: f64,
    /// Eccentricity ratio ε = e/c of the cage.
    pub eccentricity_ratio: f64,
    /// Minimum film thickness c(1 − ε), m.
    pub min_film_m: f64,
    /// Friction coefficient f = |T|/(R F_RS) (0 without load).
    pub friction_coefficient: f64,
    /// Dissipated power |T (ω₀ − ω_land)|, W.
    pub power_w: f64,
    /// The hydrodynamic capacity was exceeded: ε clamped at the model's maximum.
    pub saturated: bool,
}

/// A cage–land friction model.
pub trait QuasiStaticLandModel: Send + Sync {
    /// Evaluates the land contact.
    fn evaluate(&self, input: &CageLandInput) -> CageLandOutput;
    /// Short description for reports.
    fn name(&self) -> &'static str;
}

/// Short (Ocvirk) journal bearing, π-film, standard form (not in the seeds; Hamrock,
/// *Fundamentals of Fluid Film Lubrication*, short-bearing theory):
///
/// * load capacity per rail W = η U L³/(4c²) · ε √(π²(1 − ε²) + 16ε²)/(1 − ε²)², with the
///   surface speed U = R |ω₀ + ω_land − 2ω_load| (both members rotating under a load of speed
///   ω_load);
/// * the eccentricity follows from W(ε)·rails = F_ext + m_c ε c ω₀² (the centrifugal force of
///   the displaced cage, SPEC §5.5 proposal F_cs = m_c e ω₀²);
/// * friction moment on the cage: the Couette shear of the full film,
///   T = −rails · 2π η R³ L (ω₀ − ω_land)/(c √(1 − ε²)) (Petroff with the eccentricity factor;
///   the pressure-induced moment e W sin φ/2 ≤ c W/2 is neglected: c W/2 is below 1 % of the
///   shear moment for cage loads);
/// * narrow cage rails carry little hydrodynamic load (∝ L³/c²): beyond the capacity at
///   `max_eccentricity_ratio` the excess pressing force is carried by asperity contact with the
///   friction coefficient `boundary_friction` (mixed lubrication of the land; proposal, not in
///   the seeds), adding −sgn(ω₀ − ω_land) f_b (F_RS − W_max) R to the moment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShortBearing {
    /// Largest eccentricity ratio (film collapse beyond). Default 0.98.
    pub max_eccentricity_ratio: f64,
    /// Friction coefficient of the load in excess of the hydrodynamic capacity. Default 0.1
    /// (the large-slip limit of Kragelsky's boundary friction (2.10), SPEC §4.4).
    pub boundary_friction: f64,
}

impl Default for ShortBearing {
    fn default() -> Self {
        Self {
            max_eccentricity_ratio: 0.98,
            boundary_friction: 0.1,
        }
    }
}

impl ShortBearing {
    /// Dimensionless Ocvirk load function ε √(π²(1 − ε²) + 16ε²)/(1 − ε²)².
    pub fn load_function(eps: f64) -> f64 {
        let q = 1.0 - eps * eps;
        eps * (PI * PI * q + 16.0 * eps * eps).sqrt() / (q * q)
    }
}

impl QuasiStaticLandModel for ShortBearing {
    fn name(&self) -> &'static str {
        "short (Ocvirk) journal bearing"
    }

    fn evaluate(&self, inp: &CageLandInput) -> CageLandOutput {
        let c = inp.radial_clearance_m;
        let r = inp.land_radius_m;
        let l = inp.rail_width_m;
        let eta = inp.viscosity_pa_s;
        let rails = inp.rails.max(1) as f64;
        if !(c > 0.0 && r > 0.0 && l > 0.0 && eta > 0.0) {
            return CageLandOutput::default();
        }
        let u =
            r * (inp.cage_speed_rad_s + inp.land_speed_rad_s - 2.0 * inp.load_speed_rad_s).abs();
        let k = rails * eta * u * l * l * l / (4.0 * c * c);
        let kc = inp.cage_mass_kg * c * inp.cage_speed_rad_s * inp.cage_speed_rad_s;
        let f_ext = inp.roller_force_n.max(0.0);
        let capacity = |e: f64| k * Self::load_function(e);
        let e_max = self.max_eccentricity_ratio.clamp(0.0, 0.999);
        let (eps, saturated) =
            film_equilibrium(&capacity, kc, f_ext, e_max, f_ext == 0.0 && k * PI >= kc);
        let dw = inp.cage_speed_rad_s - inp.land_speed_rad_s;
        let film_torque = -rails * couette_land_torque(eta, dw, r, l, c, eps);
        land_output(
            inp,
            eps,
            saturated,
            capacity(eps),
            film_torque,
            kc,
            self.boundary_friction,
        )
    }
}

/// Eccentricity ratio at which the film carries the pressing force: the root of
/// `capacity(ε) − k_c ε − F_ext` on [0, ε_max] (bisection, 60 halvings; capacity − k_c ε is
/// continuous and the root is bracketed by g(0) = −F_ext ≤ 0 < g(ε_max)), ε_max with
/// `saturated` when the film cannot carry it, 0 when `unloaded`.
fn film_equilibrium(
    capacity: &dyn Fn(f64) -> f64,
    kc: f64,
    f_ext: f64,
    e_max: f64,
    unloaded: bool,
) -> (f64, bool) {
    let g = |e: f64| capacity(e) - kc * e - f_ext;
    if unloaded {
        return (0.0, false);
    }
    if g(e_max) <= 0.0 {
        return (e_max, true);
    }
    let (mut a, mut b) = (0.0, e_max);
    for _ in 0..60 {
        let m = 0.5 * (a + b);
        if g(m) > 0.0 {
            b = m;
        } else {
            a = m;
        }
    }
    (0.5 * (a + b), false)
}

/// Land output at the equilibrium eccentricity: the film torque plus asperity friction on the
/// pressing force the film cannot carry (sign smoothed over ±1 mm/s sliding).
fn land_output(
    inp: &CageLandInput,
    eps: f64,
    saturated: bool,
    film_capacity: f64,
    film_torque: f64,
    kc: f64,
    boundary_friction: f64,
) -> CageLandOutput {
    let r = inp.land_radius_m;
    let dw = inp.cage_speed_rad_s - inp.land_speed_rad_s;
    let pressing = inp.roller_force_n.max(0.0) + kc * eps;
    let excess = if saturated {
        (pressing - film_capacity).max(0.0)
    } else {
        0.0
    };
    let sign = rolldyn_lubrication::traction::regularisation(dw * r, 1e-3);
    let torque = film_torque - sign * boundary_friction * excess * r;
    CageLandOutput {
        torque_on_cage_n_m: torque,
        pressing_force_n: pressing,
        eccentricity_ratio: eps,
        min_film_m: inp.radial_clearance_m * (1.0 - eps),
        friction_coefficient: if pressing > 0.0 {
            torque.abs() / (r * pressing)
        } else {
            0.0
        },
        power_w: (torque * dw).abs(),
        saturated,
    }
}

/// The dynamics' plain pair-14 contact in the quasi-static cage balance (theory §3.3): no
/// film, so the cage rests on the land with its clearance taken up (e = c) under the pressing
/// force F_RS = m_c c ω₀² + √(F_SB² + F_SГ²) (SPEC §5.5), and drags on it with the two-level
/// friction μ(v) F_RS of the sliding speed v = R (ω₀ − ω_land) (SPEC §3.4): moment −μ(v) F_RS R.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLand {
    /// the pair-14 two-level friction law of the dynamics
    pub friction: TwoLevelFriction,
}

impl QuasiStaticLandModel for ContactLand {
    fn name(&self) -> &'static str {
        "plain contact, two-level friction (pair 14)"
    }

    fn evaluate(&self, i: &CageLandInput) -> CageLandOutput {
        let (r, c, w0) = (i.land_radius_m, i.radial_clearance_m, i.cage_speed_rad_s);
        let slip = w0 - i.land_speed_rad_s;
        let pressing = i.cage_mass_kg * c * w0 * w0 + i.roller_force_n;
        let mu = self.friction.coefficient(r * slip);
        let torque = -mu * pressing * r;
        CageLandOutput {
            torque_on_cage_n_m: torque,
            pressing_force_n: pressing,
            eccentricity_ratio: 1.0,
            min_film_m: 0.0,
            friction_coefficient: mu.abs(),
            power_w: (torque * slip).abs(),
            saturated: false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn input(load: f64) -> CageLandInput {
        CageLandInput {
            land_radius_m: 0.046,
            rail_width_m: 2e-3,
            rails: 2,
            radial_clearance_m: 0.2e-3,
            viscosity_pa_s: 0.02,
            cage_speed_rad_s: 200.0,
            land_speed_rad_s: 0.0,
            load_speed_rad_s: 0.0,
            roller_force_n: load,
            cage_mass_kg: 0.05,
        }
    }

    #[test]
    fn concentric_cage_gives_petroff() {
        let m = ShortBearing::default();
        let mut inp = input(0.0);
        inp.cage_mass_kg = 0.0;
        let out = m.evaluate(&inp);
        assert_eq!(out.eccentricity_ratio, 0.0);
        let petroff = 2.0 * 2.0 * PI * 0.02 * 0.046f64.powi(3) * 2e-3 * 200.0 / 0.2e-3;
        assert!((out.torque_on_cage_n_m + petroff).abs() < 1e-12 * petroff);
    }

    #[test]
    fn load_balance_and_monotone_eccentricity() {
        let m = ShortBearing::default();
        let mut last = 0.0;
        let mut last_torque = 0.0;
        for load in [0.001, 0.01, 1.0, 10.0, 50.0, 200.0] {
            // without the cage's own centrifugal force (which alone saturates this light film)
            let inp = CageLandInput {
                cage_mass_kg: 0.0,
                ..input(load)
            };
            let out = m.evaluate(&inp);
            assert!(out.eccentricity_ratio >= last);
            assert!(
                out.torque_on_cage_n_m.abs() > last_torque,
                "{load}: {out:?} {last_torque}"
            );
            last = out.eccentricity_ratio;
            last_torque = out.torque_on_cage_n_m.abs();
            if !out.saturated {
                let u = inp.land_radius_m * inp.cage_speed_rad_s;
                let w = 2.0 * inp.viscosity_pa_s * u * inp.rail_width_m.powi(3)
                    / (4.0 * inp.radial_clearance_m.powi(2))
                    * ShortBearing::load_function(out.eccentricity_ratio);
                assert!((w - out.pressing_force_n).abs() < 1e-9 * load);
            }
        }
    }

    /// The contact land drags the cage back towards the land speed with μ_d F_RS R once the
    /// sliding speed exceeds v_d, and carries no moment without slip.
    #[test]
    fn contact_land_is_two_level_friction_of_the_pressing_force() {
        let friction = TwoLevelFriction {
            mu_static: 0.02,
            mu_dynamic: 0.01,
            v_static: 1e-2,
            v_dynamic: 1e-1,
        };
        let land = ContactLand { friction };
        let input = CageLandInput {
            land_radius_m: 0.1,
            rail_width_m: 0.01,
            rails: 2,
            radial_clearance_m: 2.5e-4,
            viscosity_pa_s: 0.01,
            cage_speed_rad_s: 400.0,
            land_speed_rad_s: 850.0,
            load_speed_rad_s: 850.0,
            roller_force_n: 50.0,
            cage_mass_kg: 0.5,
        };
        let out = land.evaluate(&input);
        let pressing = 0.5 * 2.5e-4 * 400.0 * 400.0 + 50.0;
        assert!((out.pressing_force_n - pressing).abs() < 1e-12);
        let expected = friction.mu_dynamic * pressing * 0.1;
        assert!((out.torque_on_cage_n_m - expected).abs() < 1e-12 * expected);
        let still = CageLandInput {
            cage_speed_rad_s: 850.0,
            ..input
        };
        assert_eq!(land.evaluate(&still).torque_on_cage_n_m, 0.0);
    }
}

/// Finite-length journal-bearing land model (SPEC §8.6): the Reynolds crate's fast
/// [`rolldyn_reynolds::cage_land::CageLand`] — short-bearing theory corrected by a table of the
/// finite Reynolds solver (force within 0.4 %, torque within 0.1 % of the full solver). The
/// table is built for the land geometry at the first evaluation (≈ 0.3 s) and rebuilt only if
/// the operating geometry changes. Beyond the film capacity at `max_eccentricity_ratio` the
/// excess pressing force is carried by asperity contact as in [`ShortBearing`].
#[derive(Debug)]
pub struct FiniteLand {
    /// Largest eccentricity ratio of the film (default 0.98).
    pub max_eccentricity_ratio: f64,
    /// Friction coefficient of the excess load (default 0.1, as [`ShortBearing`]).
    pub boundary_friction: f64,
    /// Inner-ring land (cage bore on the land) or outer-ring land.
    pub inner_land: bool,
    /// Fill fraction of the land clearance (1: flooded; a starved land below 1,
    /// [`rolldyn_reynolds::cage_land`] module doc). Default 1.
    pub fill_fraction: f64,
    table: std::sync::Mutex<Option<([f64; 3], rolldyn_reynolds::cage_land::CageLand)>>,
}

impl FiniteLand {
    /// A land model for a cage guided on the inner (`inner_land`) or outer ring.
    pub fn new(inner_land: bool) -> Self {
        Self {
            max_eccentricity_ratio: 0.98,
            boundary_friction: 0.1,
            inner_land,
            fill_fraction: 1.0,
            table: std::sync::Mutex::new(None),
        }
    }

    /// Runs `f` with the land table of this geometry (built once per geometry).
    fn with_land<R>(
        &self,
        geometry: [f64; 3],
        f: impl FnOnce(&rolldyn_reynolds::cage_land::CageLand) -> R,
    ) -> Option<R> {
        use rolldyn_reynolds::cage_land::{
            CageLand, CageLandGeometry, CageLandOptions, LandPosition,
        };
        let mut guard = self.table.lock().ok()?;
        let same = |a: &[f64; 3]| {
            a.iter()
                .zip(&geometry)
                .all(|(x, y)| (x - y).abs() <= 1e-9 * y.abs())
        };
        if !guard.as_ref().is_some_and(|(g, _)| same(g)) {
            let geom = CageLandGeometry {
                radius: geometry[0],
                width: geometry[1],
                clearance: geometry[2],
                position: if self.inner_land {
                    LandPosition::InnerRing
                } else {
                    LandPosition::OuterRing
                },
            };
            let options = CageLandOptions {
                max_eccentricity: self.max_eccentricity_ratio,
                fill_fraction: self.fill_fraction,
                ..CageLandOptions::default()
            };
            *guard = Some((geometry, CageLand::new(geom, &options).ok()?));
        }
        guard.as_ref().map(|(_, land)| f(land))
    }
}

impl QuasiStaticLandModel for FiniteLand {
    fn name(&self) -> &'static str {
        "finite journal bearing (Reynolds crate table)"
    }

    fn evaluate(&self, inp: &CageLandInput) -> CageLandOutput {
        let geometry = [inp.land_radius_m, inp.rail_width_m, inp.radial_clearance_m];
        self.with_land(geometry, |land| self.evaluate_with(land, inp))
            .unwrap_or_else(|| ShortBearing::default().evaluate(inp))
    }
}

impl FiniteLand {
    fn evaluate_with(
        &self,
        land: &rolldyn_reynolds::cage_land::CageLand,
        inp: &CageLandInput,
    ) -> CageLandOutput {
        let (c, eta) = (inp.radial_clearance_m, inp.viscosity_pa_s);
        let rails = inp.rails.max(1) as f64;
        if eta.is_nan() || eta <= 0.0 {
            return CageLandOutput::default();
        }
        // In the frame of the load direction the film sees the cage and land speeds relative to it.
        let (wc, wl) = (
            inp.cage_speed_rad_s - inp.load_speed_rad_s,
            inp.land_speed_rad_s - inp.load_speed_rad_s,
        );
        let at = |eps: f64| land.evaluate([eps * c, 0.0], [0.0, 0.0], wc, wl, eta);
        let capacity = |eps: f64| {
            let f = at(eps).force_n;
            rails * f[0].hypot(f[1])
        };
        let kc = inp.cage_mass_kg * c * inp.cage_speed_rad_s * inp.cage_speed_rad_s;
        let f_ext = inp.roller_force_n.max(0.0);
        let unloaded = f_ext == 0.0 && capacity(1e-3) >= kc * 1e-3;
        let (eps, saturated) =
            film_equilibrium(&capacity, kc, f_ext, self.max_eccentricity_ratio, unloaded);
        land_output(
            inp,
            eps,
            saturated,
            capacity(eps),
            rails * at(eps).torque_nm,
            kc,
            self.boundary_friction,
        )
    }
}
