//! The roller ↔ cage bar contact law `F = K_p δⁿ + STEP(δ, 0, 0, d, C_h)·δ̇` (pair 34, SPEC
//! §3.3) derived from physics (docs/theory.md §2.3.1, "Roller–cage bar contact law"):
//!
//! * elastic part — the bar bends and shears as a beam clamped in the cage's side rims, in
//!   series with the line contact of the roller on the bar face; the sum is fitted by `K_p δⁿ`;
//! * damping — the oil squeeze film between roller and bar (rigid cylinder on a plane, the
//!   outlet half cavitated) sets the coefficient of restitution of a roller striking the bar;
//!   `C_h` is chosen so that the STEP-damped law gives the same restitution at a reference
//!   impact speed, with `d` = the film thickness at which the asperities meet.
//!
//! The hydrodynamic lift of the roller spinning against the bar is left out of the restitution
//! match (it makes the restitution higher, so [`derive`] gives its lower bound); the lubricated
//! force law of [`crate::bar_force`] carries it explicitly, and [`DerivedBarLaw::force_law`]
//! builds either law for the dynamics.
//!
//! SI units throughout (m, N, Pa, Pa·s, kg).

use crate::bar_force::{BarFilm, BarFilmSettings, BarForceLaw, ElasticBarLaw, LubricatedBarLaw};
use crate::damping::SliceDamping;
use crate::hertz::{LineApproachModel, LineContact, reduced_modulus};
use crate::squeeze_film::SqueezeFilm;
use rolldyn_geometry::CylindricalRollerBearing;
use std::f64::consts::PI;

pub use rolldyn_geometry::BarSection;

/// Cowper's shear coefficient of a rectangle, `κ = 10(1+ν)/(12+11ν)`.
pub fn shear_coefficient(poisson_ratio: f64) -> f64 {
    10.0 * (1.0 + poisson_ratio) / (12.0 + 11.0 * poisson_ratio)
}

/// A bar clamped at both ends (the cage side rims) over `span`, loaded by two equal forces
/// `F/2` at `offset` from either end (the roller's two bar points; `offset = span/2` is one
/// force at mid-span).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClampedBar {
    pub section: BarSection,
    /// Span = the pocket's axial size (m).
    pub span: f64,
    /// Distance of each load point from its clamped end, `0 < a ≤ span/2` (m).
    pub offset: f64,
    /// Young's modulus (Pa) and Poisson's ratio of the cage.
    pub youngs_modulus: f64,
    pub poisson_ratio: f64,
}

impl ClampedBar {
    /// Bending compliance (m/N of the total force F) under the load points: Euler–Bernoulli
    /// clamped–clamped influence coefficients (Roark, Table 8.1 case 1e)
    /// `y(a; a) = a³(L−a)³/(3EIL³)`, `y(a; L−a) = a⁴(3L² − 6aL + 2a²)/(6EIL³)`, each load F/2.
    pub fn bending_compliance(&self) -> f64 {
        let (l, a) = (self.span, self.offset.min(0.5 * self.span));
        let ei = self.youngs_modulus * self.section.second_moment;
        let own = a.powi(3) * (l - a).powi(3) / (3.0 * ei * l.powi(3));
        let other = a.powi(4) * (3.0 * l * l - 6.0 * a * l + 2.0 * a * a) / (6.0 * ei * l.powi(3));
        0.5 * (own + other)
    }

    /// Shear compliance (m/N): the shear force F/2 over the outer segments of length `a`,
    /// `δ_s = (F/2)·a/(κGA)` (Timoshenko's shear term, in series with bending).
    pub fn shear_compliance(&self) -> f64 {
        let g = self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio));
        let kappa = shear_coefficient(self.poisson_ratio);
        let a = self.offset.min(0.5 * self.span);
        0.5 * a / (kappa * g * self.section.area)
    }
}

/// The bar in series with the line contact of the roller on the bar face.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BarCompliance {
    pub bar: ClampedBar,
    /// Roller (radius R_w) on the flat bar face over the contact length.
    pub contact: LineContact,
}

impl BarCompliance {
    /// Approach of the roller towards the bar (m) at force `f` (N): bending + shear + line
    /// contact (Palmgren's law rescaled to E', [`LineApproachModel::PalmgrenScaled`]) in series.
    pub fn approach(&self, f: f64) -> f64 {
        (self.bar.bending_compliance() + self.bar.shear_compliance()) * f
            + self.contact.approach(f, LineApproachModel::PalmgrenScaled)
    }
}

/// The elastic power law `F = K_p δⁿ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PowerLaw {
    /// K_p (N/mⁿ).
    pub k_p: f64,
    /// n.
    pub exponent: f64,
}

impl PowerLaw {
    pub fn force(&self, delta: f64) -> f64 {
        if delta > 0.0 {
            self.k_p * delta.powf(self.exponent)
        } else {
            0.0
        }
    }

    /// Least-squares fit of `ln F = ln K_p + n ln δ` to `approach` at `points` forces spaced
    /// evenly in log F over `[f_min, f_max]`; returns the law and the largest relative force
    /// error `|K_p δ(F)ⁿ / F − 1|` over those points.
    pub fn fit(
        approach: impl Fn(f64) -> f64,
        (f_min, f_max): (f64, f64),
        points: usize,
    ) -> (Self, f64) {
        let samples: Vec<(f64, f64)> = (0..points)
            .map(|i| {
                let t = i as f64 / (points - 1).max(1) as f64;
                let f = f_min * (f_max / f_min).powf(t);
                (approach(f).ln(), f.ln())
            })
            .collect();
        let n = samples.len() as f64;
        let (sx, sy) = samples
            .iter()
            .fold((0.0, 0.0), |(a, b), (x, y)| (a + x, b + y));
        let (mx, my) = (sx / n, sy / n);
        let (sxy, sxx) = samples.iter().fold((0.0, 0.0), |(a, b), (x, y)| {
            (a + (x - mx) * (y - my), b + (x - mx) * (x - mx))
        });
        let exponent = sxy / sxx;
        let law = Self {
            k_p: (my - exponent * mx).exp(),
            exponent,
        };
        let error = samples
            .iter()
            .map(|&(x, y)| (law.force(x.exp()) / y.exp() - 1.0).abs())
            .fold(0.0, f64::max);
        (law, error)
    }
}

/// Outcome of a normal impact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Impact {
    /// Coefficient of restitution `e = v_out/v_in` (0 if the roller stops in the film).
    pub restitution: f64,
    /// Largest contact force (N).
    pub peak_force: f64,
    /// Largest penetration reached (m; 0 when the roller stops in the film before contact).
    pub max_penetration: f64,
}

/// Numerical settings of the impact integration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactSettings {
    /// Steps per undamped contact time estimate `π√(m/k)`. Default 4000: the restitution of
    /// the undamped Hertz impact is then 1 within 1e-6 (test `undamped_impact_restitutes`).
    pub steps_per_contact: usize,
}

impl Default for ImpactSettings {
    fn default() -> Self {
        Self {
            steps_per_contact: 4000,
        }
    }
}

/// Penetration of the undamped impact, `½mv² = K_p δⁿ⁺¹/(n+1)` (m).
pub fn undamped_penetration(mass: f64, speed: f64, elastic: PowerLaw) -> f64 {
    let n = elastic.exponent;
    (0.5 * mass * speed * speed * (n + 1.0) / elastic.k_p).powf(1.0 / (n + 1.0))
}

/// Tangent stiffness `n K_p δⁿ⁻¹` at the undamped impact penetration (N/m).
fn impact_stiffness(mass: f64, speed: f64, elastic: PowerLaw) -> f64 {
    let delta = undamped_penetration(mass, speed, elastic);
    elastic.k_p * elastic.exponent * delta.powf(elastic.exponent - 1.0)
}

/// The largest `C_h` worth using with the ramp `d`: the one whose ramped coefficient
/// `STEP(δ_m, 0, 0, d, C_h)` at the undamped impact penetration `δ_m` is the critical damping
/// `2√(k m)` of the tangent stiffness there. More damping no longer removes rebound, it only
/// raises the force at first touch.
pub fn critical_damping(mass: f64, speed: f64, elastic: PowerLaw, d: f64) -> f64 {
    let delta = undamped_penetration(mass, speed, elastic);
    let critical = 2.0 * (impact_stiffness(mass, speed, elastic) * mass).sqrt();
    critical / SliceDamping::new(1.0, d).coefficient(delta)
}

/// Roller of `mass` hitting at `speed` a contact of force law `force(δ, δ̇)` (≥ 0) with the
/// elastic part `elastic`, whose damping never exceeds `c_max`: integrates `m δ̈ = −F` by RK4
/// from first touch until it separates.
pub fn impact(
    mass: f64,
    speed: f64,
    elastic: PowerLaw,
    c_max: f64,
    force: impl Fn(f64, f64) -> f64,
    settings: ImpactSettings,
) -> Impact {
    let stiffness = impact_stiffness(mass, speed, elastic);
    let dt = (PI * (mass / stiffness).sqrt() / settings.steps_per_contact as f64)
        .min(0.5 * mass / c_max.max(f64::MIN_POSITIVE));
    let accel = |d: f64, v: f64| -force(d, v) / mass;
    let (mut d, mut v, mut peak, mut deepest) = (0.0_f64, speed, 0.0_f64, 0.0_f64);
    let max_steps = 1000 * settings.steps_per_contact;
    for _ in 0..max_steps {
        let (k1d, k1v) = (v, accel(d, v));
        let (k2d, k2v) = (
            v + 0.5 * dt * k1v,
            accel(d + 0.5 * dt * k1d, v + 0.5 * dt * k1v),
        );
        let (k3d, k3v) = (
            v + 0.5 * dt * k2v,
            accel(d + 0.5 * dt * k2d, v + 0.5 * dt * k2v),
        );
        let (k4d, k4v) = (v + dt * k3v, accel(d + dt * k3d, v + dt * k3v));
        d += dt / 6.0 * (k1d + 2.0 * k2d + 2.0 * k3d + k4d);
        v += dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        peak = peak.max(force(d, v));
        deepest = deepest.max(d);
        if d <= 0.0 {
            break;
        }
    }
    Impact {
        restitution: (-v / speed).max(0.0),
        peak_force: peak,
        max_penetration: deepest,
    }
}

/// Impact through the squeeze film: the roller crosses the film down to `h_contact` (where the
/// asperities meet), loses [`SqueezeFilm::speed_loss`], hits the elastic law with the film's
/// damping frozen at `λ(h_contact)`, and crosses the film again on the way out.
pub fn film_impact(
    mass: f64,
    speed: f64,
    elastic: PowerLaw,
    film: SqueezeFilm,
    h_contact: f64,
    settings: ImpactSettings,
) -> Impact {
    let loss = film.speed_loss(mass, h_contact);
    let v_touch = speed - loss;
    let film_peak = film.peak_force(mass, speed, h_contact);
    if v_touch <= 0.0 {
        return Impact {
            restitution: 0.0,
            peak_force: film_peak,
            max_penetration: 0.0,
        };
    }
    let c = film.damping(h_contact);
    let contact = impact(
        mass,
        v_touch,
        elastic,
        c,
        |d, v| (elastic.force(d) + c * v).max(0.0),
        settings,
    );
    Impact {
        restitution: ((contact.restitution * v_touch - loss) / speed).max(0.0),
        peak_force: contact.peak_force.max(film_peak),
        max_penetration: contact.max_penetration,
    }
}

/// The seed's STEP-damped law `K_p δⁿ + STEP(δ, 0, 0, d, C_h)·δ̇` (clamped ≥ 0) as an impact.
pub fn step_law_impact(
    mass: f64,
    speed: f64,
    elastic: PowerLaw,
    damping: SliceDamping,
    settings: ImpactSettings,
) -> Impact {
    impact(
        mass,
        speed,
        elastic,
        damping.c_max,
        |d, v| damping.normal_force(elastic.force(d), d, v),
        settings,
    )
}

/// `C_h` (N·s/m) for which the STEP law with ramp `d` restitutes like `target` at `speed`
/// (bisection in log C_h over 10⁻³…10⁷ N·s/m; the restitution falls monotonically with C_h).
pub fn matching_damping(
    mass: f64,
    speed: f64,
    elastic: PowerLaw,
    d: f64,
    target: f64,
    settings: ImpactSettings,
) -> f64 {
    let e = |c: f64| step_law_impact(mass, speed, elastic, SliceDamping::new(c, d), settings);
    let (mut lo, mut hi) = (1e-3_f64.ln(), 1e7_f64.ln());
    if e(lo.exp()).restitution <= target {
        return 0.0;
    }
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if e(mid.exp()).restitution > target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (0.5 * (lo + hi)).exp()
}

/// Everything the derivation needs about one bearing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BarLawInputs {
    pub compliance: BarCompliance,
    pub film: SqueezeFilm,
    /// Roller mass (kg).
    pub roller_mass: f64,
    /// Film thickness at which the asperities meet (m): the STEP ramp `d`.
    pub contact_film: f64,
}

impl BarLawInputs {
    /// The inputs of a bearing with a cage: bar section from the cage bore, outside diameter,
    /// window and pocket count; span = axial pocket size; load points at the roller's bar
    /// points ± the working half-length (the dynamics' `bar_x`); contact and film length =
    /// the straight part of a crowned roller (else the working length); oil `viscosity` (Pa·s)
    /// at the cage temperature; the asperities meet at the film of Λ = 1 (seed 000 (1.2)) for
    /// the roller's and the cage's roughness. `None` without a cage or with windows wider than
    /// the bar pitch.
    pub fn of_bearing(bearing: &CylindricalRollerBearing, viscosity: f64) -> Option<Self> {
        let cage = bearing.cage.as_ref()?;
        let roller = &bearing.roller;
        let film = BarFilm::of_bearing(bearing, viscosity, &BarFilmSettings::default())?;
        let section = cage
            .pocket
            .bar_section(&bearing.pocket_context(cage))
            .ok()?;
        let half_working = roller.profile.chamfer_start().min(0.5 * roller.length);
        let span = cage.pocket.axial;
        let length = roller.bar_contact_length();
        let radius = film.radius;
        let (rm, cm) = (&roller.material, &cage.material);
        Some(Self {
            compliance: BarCompliance {
                bar: ClampedBar {
                    section,
                    span,
                    offset: (0.5 * span - half_working).max(0.0),
                    youngs_modulus: cm.youngs_modulus,
                    poisson_ratio: cm.poisson_ratio,
                },
                contact: LineContact {
                    reduced_radius: radius,
                    reduced_modulus: reduced_modulus(
                        rm.youngs_modulus,
                        rm.poisson_ratio,
                        cm.youngs_modulus,
                        cm.poisson_ratio,
                    ),
                    length,
                },
            },
            film: SqueezeFilm {
                viscosity,
                length,
                radius,
            },
            roller_mass: roller.mass_properties.mass,
            contact_film: film.contact_film,
        })
    }

    /// The oil film between roller and bar of these inputs, ending at the cutoff of `settings`.
    pub fn bar_film(&self, settings: &BarFilmSettings) -> BarFilm {
        BarFilm {
            viscosity: self.film.viscosity,
            radius: self.film.radius,
            contact_film: self.contact_film,
            cutoff: settings.cutoff_ratio * self.film.radius,
        }
    }
}

/// Settings of the derivation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DerivationSettings {
    /// Force range of the power-law fit (N). Default 1…500 N: the bar forces the dynamics
    /// produces (seed Table 3.2: 10–23 N; rolldyn with the old law up to ≈ 470 N).
    pub force_range: (f64, f64),
    /// Fit points, evenly in log F. Default 41.
    pub fit_points: usize,
    /// Impact speed at which the STEP law is matched to the film (m/s). Default 0.1 m/s: the
    /// middle (in log) of the 0.01–0.5 m/s relative speeds of roller and bar.
    pub reference_speed: f64,
    pub impact: ImpactSettings,
}

impl Default for DerivationSettings {
    fn default() -> Self {
        Self {
            force_range: (1.0, 500.0),
            fit_points: 41,
            reference_speed: 0.1,
            impact: ImpactSettings::default(),
        }
    }
}

/// The derived pair-34 numbers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DerivedBarLaw {
    pub elastic: PowerLaw,
    /// Largest relative force error of the fit over the force range.
    pub fit_error: f64,
    /// C_h (N·s/m).
    pub c_h: f64,
    /// d (m).
    pub d: f64,
    /// Restitution through the film at the reference speed, which the STEP law reproduces.
    pub restitution: f64,
    /// The film damps more than critically (it stops the roller before metal contact, or
    /// nearly): `C_h` is [`critical_damping`] instead of the restitution match.
    pub critically_capped: bool,
}

/// Which pair-34 force law to build.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum BarLawKind {
    /// `K_p δⁿ + STEP(δ, 0, 0, d, C_h)·δ̇`, C_h matched to the film's restitution.
    #[default]
    Elastic,
    /// The film (squeeze and wedge) explicitly, the elastic law below the asperity film.
    Lubricated,
}

impl DerivedBarLaw {
    /// The force law of `kind` over the contact length of `inputs`. The lubricated law's
    /// elastic part has no STEP damping (`C_h = 0`): the film it carries is the damper that
    /// `C_h` stands for in the elastic law, and adding both would count it twice.
    pub fn force_law(
        &self,
        inputs: &BarLawInputs,
        kind: BarLawKind,
        film: &BarFilmSettings,
    ) -> BarForceLaw {
        let elastic = ElasticBarLaw {
            k_p: self.elastic.k_p,
            exponent: self.elastic.exponent,
            c_h: self.c_h,
            d: self.d,
            reference_length: inputs.film.length,
        };
        match kind {
            BarLawKind::Elastic => BarForceLaw::Elastic(elastic),
            BarLawKind::Lubricated => BarForceLaw::Lubricated(LubricatedBarLaw {
                elastic: ElasticBarLaw {
                    c_h: 0.0,
                    ..elastic
                },
                film: inputs.bar_film(film),
            }),
        }
    }
}

/// Derives `K_p`, `n` (fit of the series compliance) and `C_h`, `d` (restitution of the squeeze
/// film at the reference speed, at most [`critical_damping`]) for a bearing's inputs.
pub fn derive(inputs: &BarLawInputs, settings: &DerivationSettings) -> DerivedBarLaw {
    let (elastic, fit_error) = PowerLaw::fit(
        |f| inputs.compliance.approach(f),
        settings.force_range,
        settings.fit_points,
    );
    let (m, v, d) = (
        inputs.roller_mass,
        settings.reference_speed,
        inputs.contact_film,
    );
    let restitution = film_impact(m, v, elastic, inputs.film, d, settings.impact).restitution;
    let matched = matching_damping(m, v, elastic, d, restitution, settings.impact);
    let cap = critical_damping(m, v, elastic, d);
    DerivedBarLaw {
        elastic,
        fit_error,
        c_h: matched.min(cap),
        d,
        restitution,
        critically_capped: matched > cap,
    }
}

/// [`derive`] for a bearing with a cage and the oil `viscosity` (Pa·s) at the cage temperature
/// ([`BarLawInputs::of_bearing`]); `None` without a cage.
pub fn derive_for_bearing(
    bearing: &CylindricalRollerBearing,
    viscosity: f64,
    settings: &DerivationSettings,
) -> Option<(BarLawInputs, DerivedBarLaw)> {
    let inputs = BarLawInputs::of_bearing(bearing, viscosity)?;
    let law = derive(&inputs, settings);
    Some((inputs, law))
}

#[cfg(test)]
mod tests {
    use super::*;

    const E: f64 = 211e9;

    fn rectangle_bar(span: f64, offset: f64) -> ClampedBar {
        // a rectangular bar 10 mm deep (radial), 4 mm wide (tangential)
        let section = BarSection {
            depth: 10e-3,
            width_inner: 4e-3,
            width_outer: 4e-3,
            width_min: 4e-3,
            radius_of_min: 0.0,
            area: 40e-6,
            centroid_radius: 0.0,
            second_moment: 10e-3 * 64e-9 / 12.0,
            second_moment_radial: 4e-3 * 1e-6 / 12.0,
        };
        ClampedBar {
            section,
            span,
            offset,
            youngs_modulus: E,
            poisson_ratio: 0.3,
        }
    }

    #[test]
    fn mid_span_beam_by_hand() {
        // one force at mid-span: δ = FL³/(192EI) + FL/(4κGA)
        let bar = rectangle_bar(15e-3, 7.5e-3);
        let ei = E * bar.section.second_moment;
        let hand = 15e-3_f64.powi(3) / (192.0 * ei);
        assert!((bar.bending_compliance() / hand - 1.0).abs() < 1e-12);
        let g = E / 2.6;
        let kappa = 10.0 * 1.3 / (12.0 + 3.3);
        let hand_shear = 15e-3 / (4.0 * kappa * g * 40e-6);
        assert!((bar.shear_compliance() / hand_shear - 1.0).abs() < 1e-12);
        // loads at the clamps: nothing bends
        let stiff = rectangle_bar(15e-3, 0.0);
        assert_eq!(stiff.bending_compliance() + stiff.shear_compliance(), 0.0);
    }

    fn compliance(bar: ClampedBar) -> BarCompliance {
        BarCompliance {
            bar,
            contact: LineContact {
                reduced_radius: 7.5e-3,
                reduced_modulus: reduced_modulus(208e9, 0.3, E, 0.3),
                length: 5e-3,
            },
        }
    }

    #[test]
    fn series_limits() {
        // rigid bar → the line contact alone; the contact term is sub-linear (exponent 0.9)
        let rigid = compliance(rectangle_bar(15e-3, 0.0));
        let c = rigid
            .contact
            .approach(100.0, LineApproachModel::PalmgrenScaled);
        assert_eq!(rigid.approach(100.0), c);
        let (law, err) = PowerLaw::fit(|f| rigid.approach(f), (1.0, 500.0), 21);
        assert!((law.exponent - 1.0 / 0.9).abs() < 1e-9 && err < 1e-9);
        // a slender bar → the bar alone, linear (n → 1)
        let slender = compliance(rectangle_bar(150e-3, 75e-3));
        let (law, _) = PowerLaw::fit(|f| slender.approach(f), (1.0, 500.0), 21);
        assert!((law.exponent - 1.0).abs() < 0.01, "n = {}", law.exponent);
        let bar = slender.bar.bending_compliance() + slender.bar.shear_compliance();
        assert!(slender.approach(100.0) > 100.0 * bar);
    }

    #[test]
    fn fit_reproduces_curve() {
        let c = compliance(rectangle_bar(11.25e-3, 0.625e-3));
        let (law, err) = PowerLaw::fit(|f| c.approach(f), (1.0, 500.0), 41);
        for f in [1.0, 7.0, 50.0, 300.0, 500.0] {
            let rel = law.force(c.approach(f)) / f - 1.0;
            assert!(rel.abs() <= err + 1e-12, "{f} N: {rel} > {err}");
        }
        assert!(err < 0.05, "fit error {err}");
    }

    fn roller_law() -> PowerLaw {
        PowerLaw {
            k_p: 2e9,
            exponent: 1.1,
        }
    }

    #[test]
    fn undamped_impact_restitutes() {
        let i = step_law_impact(
            0.015,
            0.1,
            roller_law(),
            SliceDamping::new(0.0, 1e-6),
            ImpactSettings::default(),
        );
        assert!((i.restitution - 1.0).abs() < 1e-6, "{}", i.restitution);
    }

    #[test]
    fn film_restitution_limits() {
        let film = |viscosity| SqueezeFilm {
            viscosity,
            length: 5e-3,
            radius: 7.5e-3,
        };
        let s = ImpactSettings::default();
        let dry = film_impact(0.015, 0.1, roller_law(), film(0.0), 3e-6, s);
        assert!((dry.restitution - 1.0).abs() < 1e-6);
        let thin = film_impact(0.015, 0.1, roller_law(), film(3e-3), 3e-6, s);
        assert!(thin.restitution < 1.0 && thin.restitution > 0.5);
        let honey = film_impact(0.015, 0.1, roller_law(), film(10.0), 3e-6, s);
        assert_eq!(honey.restitution, 0.0);
    }

    #[test]
    fn matched_step_law_restitutes_like_film() {
        let s = ImpactSettings::default();
        let target = 0.7;
        let c = matching_damping(0.015, 0.1, roller_law(), 3e-6, target, s);
        let e = step_law_impact(0.015, 0.1, roller_law(), SliceDamping::new(c, 3e-6), s);
        assert!((e.restitution - target).abs() < 1e-6, "{}", e.restitution);
    }
}
