//! Force laws of a roller slice against a cage bar face (pair 34, docs/theory.md §2.3.1),
//! evaluated per slice of the roller's contact length:
//!
//! * [`ElasticBarLaw`] — the seed's law `K_p δⁿ + STEP(δ, 0, 0, d, C_h)·δ̇` (seed 000 (2.5)–(2.8),
//!   SPEC §3.3), `K_p` and `C_h` shared over the slices in proportion to their length;
//! * [`LubricatedBarLaw`] — the oil film between roller and bar (squeeze + hydrodynamic wedge
//!   of a rigid isoviscous cylinder on a plane, [`BarFilm`]) above the film at which the
//!   asperities meet, the elastic law plus that film frozen at the asperity film below it;
//! * [`BarForceLaw`] — either, as the dynamics holds it.
//!
//! Sign conventions: `gap` is the surface separation (m), negative = elastic approach
//! `δ = −gap`; `gap_rate = d(gap)/dt` (m/s, negative = approaching). SI units throughout.

use crate::damping::SliceDamping;
use crate::squeeze_film::SqueezeFilm;
use rolldyn_geometry::CylindricalRollerBearing;
use rolldyn_lubrication::regime::film_parameter;

/// Martin's load coefficient `W₀′ = ∫q₀ dx̃` of the rigid isoviscous line contact with a
/// flooded inlet and the Reynolds (Swift–Stieber) exit `p = dp/dx = 0` at `x̃ = 0.671935`:
/// `W = 6W₀′ηVR/h` per unit length, `V = u₁ + u₂` (seed 002 (3.16)–(3.17), SPEC §8.4 with ⚠ F-66;
/// Martin 1916, Hamrock–Schmid–Jacobson *Fundamentals of Machine Elements* §13: `W = 4.9ηūR/h`
/// with the mean speed ū = V/2). Checked against `rolldyn_reynolds::line_contact::analytic::load`
/// in the Reynolds crate's tests.
pub const MARTIN_LOAD_COEFFICIENT: f64 = 0.40791;

/// `x` capped at the largest finite value (a NaN becomes that value too), so that extreme but
/// finite inputs give a finite force.
fn saturate(x: f64) -> f64 {
    x.min(f64::MAX)
}

/// The seed's elastic law with STEP damping for the whole roller–bar contact of length
/// `reference_length`; a slice of length `l` carries the share `l/reference_length` of `K_p`
/// and `C_h` (the dynamics' bar points, [`SliceDamping`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ElasticBarLaw {
    /// K_p of the whole contact (N/mⁿ).
    pub k_p: f64,
    /// n (≥ 1).
    pub exponent: f64,
    /// C_h of the whole contact (N·s/m).
    pub c_h: f64,
    /// d, the approach at which the damping reaches C_h (m).
    pub d: f64,
    /// Length of the roller's contact with the bar that K_p and C_h refer to (m).
    pub reference_length: f64,
}

impl ElasticBarLaw {
    /// `max(0, s K_p δⁿ + STEP(δ, 0, 0, d, s C_h)·δ̇)`, `s = length/reference_length`, for
    /// approach `delta` (m) and its rate `delta_rate` (m/s, > 0 approaching); 0 for `δ ≤ 0`.
    pub fn normal_force(&self, delta: f64, delta_rate: f64, length: f64) -> f64 {
        if delta <= 0.0 {
            return 0.0;
        }
        let share = saturate(length.max(0.0) / self.reference_length);
        let elastic = saturate(saturate(self.k_p * delta.powf(self.exponent)) * share);
        let damping = SliceDamping::new(saturate(share * self.c_h), self.d);
        saturate(damping.normal_force(elastic, delta, delta_rate))
    }

    fn validate(&self) -> Result<(), &'static str> {
        let positive = |x: f64| x > 0.0 && x.is_finite();
        if !(positive(self.k_p)
            && self.exponent >= 1.0
            && self.exponent.is_finite()
            && self.c_h >= 0.0
            && self.c_h.is_finite()
            && positive(self.d)
            && positive(self.reference_length))
        {
            return Err(
                "elastic bar law: need K_p > 0, n ≥ 1, C_h ≥ 0, d > 0, reference length > 0 (all finite)",
            );
        }
        Ok(())
    }
}

/// Settings of the film between roller and bar.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BarFilmSettings {
    /// The film ends at `cutoff_ratio · R_w` (the law's reach). Default 0.1: Martin's parabolic
    /// gap `h + x²/2R` needs `h ≪ R`; at R/10 the film force is below 0.5 % of its value at the
    /// asperity film of the example bearings (it falls as 1/h), and the pocket play of 2002834
    /// (0.125 mm a side) stays inside the reach, so both bars of a pocket feel the oil.
    pub cutoff_ratio: f64,
}

impl Default for BarFilmSettings {
    fn default() -> Self {
        Self { cutoff_ratio: 0.1 }
    }
}

/// Oil film between a long rigid roller (radius R_w) and the flat bar face, isoviscous, flooded:
/// per length, the wedge lift `W(h) = 12W₀′ηu_eR/h` (Martin, [`MARTIN_LOAD_COEFFICIENT`];
/// `u_e` = mean surface speed, `V = 2|u_e|`) plus the squeeze `λ(h)(−ḣ)` with the outlet half
/// cavitated ([`SqueezeFilm`]), both shifted to vanish at the `cutoff`, and clamped at ≥ 0
/// (the cavitated film carries no tension).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BarFilm {
    /// Dynamic viscosity of the oil at the cage temperature (Pa·s).
    pub viscosity: f64,
    /// Roller radius R_w (m).
    pub radius: f64,
    /// Film at which the asperities meet (m): the film of Λ = 1 (seed 000 (1.2)).
    pub contact_film: f64,
    /// Film beyond which the force is 0 (m), > `contact_film`.
    pub cutoff: f64,
}

impl BarFilm {
    /// The film of a bearing with a cage for the oil `viscosity` (Pa·s) at the cage temperature:
    /// R_w = roller radius, asperity film at Λ = 1 for the roller's and the cage's Ra, cutoff
    /// from `settings`. `None` without a cage.
    pub fn of_bearing(
        bearing: &CylindricalRollerBearing,
        viscosity: f64,
        settings: &BarFilmSettings,
    ) -> Option<Self> {
        let cage = bearing.cage.as_ref()?;
        let radius = 0.5 * bearing.roller.diameter;
        Some(Self {
            viscosity,
            radius,
            contact_film: 1.0 / film_parameter(1.0, bearing.roller.roughness_ra, cage.roughness_ra),
            cutoff: settings.cutoff_ratio * radius,
        })
    }

    /// The squeeze film of this oil over `length` (m).
    pub fn squeeze(&self, length: f64) -> SqueezeFilm {
        SqueezeFilm {
            viscosity: self.viscosity,
            length,
            radius: self.radius,
        }
    }

    /// Wedge lift per unit length at the film `h` without the cutoff shift,
    /// `12W₀′η|u_e|R/h` (N/m).
    pub fn lift_per_length(&self, h: f64, entrainment_speed: f64) -> f64 {
        12.0 * MARTIN_LOAD_COEFFICIENT * self.viscosity * entrainment_speed.abs() * self.radius / h
    }

    /// Film force (N, ≥ 0) over `length` at film `h` (m, taken ≥ `contact_film`), rate
    /// `h_rate` (m/s) and entrainment speed (m/s): `max(0, [W(h) − W(h_cut)]·l +
    /// [λ(h) − λ(h_cut)](−ḣ))` below the cutoff, 0 beyond.
    pub fn force(&self, h: f64, h_rate: f64, entrainment_speed: f64, length: f64) -> f64 {
        let h = h.max(self.contact_film);
        if h >= self.cutoff || length <= 0.0 {
            return 0.0;
        }
        let lift = saturate(
            saturate(self.lift_per_length(1.0, entrainment_speed) * length)
                * (1.0 / h - 1.0 / self.cutoff),
        );
        let damping = saturate(
            saturate(self.squeeze(length).strength()) * (h.powf(-1.5) - self.cutoff.powf(-1.5)),
        );
        saturate((lift - damping * h_rate).max(0.0))
    }

    fn validate(&self) -> Result<(), &'static str> {
        let positive = |x: f64| x > 0.0 && x.is_finite();
        if !(self.viscosity >= 0.0
            && self.viscosity.is_finite()
            && positive(self.radius)
            && positive(self.contact_film)
            && self.cutoff.is_finite()
            && self.cutoff > self.contact_film)
        {
            return Err(
                "bar film: need η ≥ 0, R_w > 0, asperity film > 0, cutoff > asperity film (all finite)",
            );
        }
        Ok(())
    }
}

/// The oil film between roller and bar down to the asperity film `h_c`, below it the elastic
/// law plus the film frozen at `h_c` (continuous in the gap):
/// `F = F_film(max(gap, h_c), ġap, u_e) + F_elastic(−gap, −ġap)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LubricatedBarLaw {
    pub elastic: ElasticBarLaw,
    pub film: BarFilm,
}

impl LubricatedBarLaw {
    pub fn normal_force(
        &self,
        gap: f64,
        gap_rate: f64,
        entrainment_speed: f64,
        length: f64,
    ) -> f64 {
        self.film.force(gap, gap_rate, entrainment_speed, length)
            + self.elastic.normal_force(-gap, -gap_rate, length)
    }
}

/// The force law of a roller slice against a cage bar face.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BarForceLaw {
    Elastic(ElasticBarLaw),
    Lubricated(LubricatedBarLaw),
}

impl BarForceLaw {
    /// Normal force (N, ≥ 0) on a slice of `length` (m) of the roller against a bar face:
    /// `gap` = surface separation (m; negative = elastic approach `δ = −gap`), `gap_rate` =
    /// d(gap)/dt (m/s), `entrainment_speed` = mean surface speed of roller and bar along the
    /// face, perpendicular to the roller axis (m/s; only the lubricated law uses it).
    pub fn normal_force(
        &self,
        gap: f64,
        gap_rate: f64,
        entrainment_speed: f64,
        length: f64,
    ) -> f64 {
        match self {
            Self::Elastic(e) => e.normal_force(-gap, -gap_rate, length),
            Self::Lubricated(l) => l.normal_force(gap, gap_rate, entrainment_speed, length),
        }
    }

    /// Largest gap at which the law can give a force (m): 0 for the elastic law, the film's
    /// cutoff for the lubricated one.
    pub fn reach(&self) -> f64 {
        match self {
            Self::Elastic(_) => 0.0,
            Self::Lubricated(l) => l.film.cutoff,
        }
    }

    /// The elastic part (the whole law when elastic).
    pub fn elastic(&self) -> &ElasticBarLaw {
        match self {
            Self::Elastic(e) => e,
            Self::Lubricated(l) => &l.elastic,
        }
    }

    /// The contact length K_p and C_h refer to (m).
    pub fn reference_length(&self) -> f64 {
        self.elastic().reference_length
    }

    /// Checks that every parameter is finite and in range.
    pub fn validate(&self) -> Result<(), &'static str> {
        self.elastic().validate()?;
        match self {
            Self::Elastic(_) => Ok(()),
            Self::Lubricated(l) => l.film.validate(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn elastic() -> ElasticBarLaw {
        ElasticBarLaw {
            k_p: 7.285e8,
            exponent: 1.1108,
            c_h: 1779.0,
            d: 3.13e-6,
            reference_length: 5e-3,
        }
    }

    fn lubricated() -> LubricatedBarLaw {
        LubricatedBarLaw {
            elastic: ElasticBarLaw {
                c_h: 0.0,
                ..elastic()
            },
            film: BarFilm {
                viscosity: 2.98e-3,
                radius: 7.5e-3,
                contact_film: 3.13e-6,
                cutoff: 0.75e-3,
            },
        }
    }

    /// At the reference length the elastic law is today's `SliceDamping` composition bit for
    /// bit; half the length carries half of K_p and C_h (the dynamics' bar points).
    #[test]
    fn elastic_law_reproduces_the_seed_law() {
        let e = elastic();
        let law = BarForceLaw::Elastic(e);
        let damping = SliceDamping::new(e.c_h, e.d);
        for (delta, rate) in [(1e-7_f64, 0.1), (2e-6, -0.05), (5e-6, 0.0), (4e-6, -10.0)] {
            let today = damping.normal_force(e.k_p * delta.powf(e.exponent), delta, rate);
            assert_eq!(law.normal_force(-delta, -rate, 30.0, 5e-3), today);
            let half = SliceDamping::new(0.5 * e.c_h, e.d).normal_force(
                0.5 * e.k_p * delta.powf(e.exponent),
                delta,
                rate,
            );
            assert_eq!(law.normal_force(-delta, -rate, 0.0, 2.5e-3), half);
        }
        assert_eq!(law.normal_force(1e-6, -1.0, 30.0, 5e-3), 0.0);
        assert_eq!(law.reach(), 0.0);
        assert!(law.validate().is_ok());
    }

    /// The film force is Martin's lift plus the half-cavitated squeeze, less their values at
    /// the cutoff (exact arithmetic: relative 1e-12 covers rounding).
    #[test]
    fn film_force_is_lift_plus_squeeze() {
        let l = lubricated();
        let f = l.film;
        let (h, rate, u, len) = (10e-6, -0.02, 19.0, 5e-3);
        let lift = 12.0 * MARTIN_LOAD_COEFFICIENT * f.viscosity * u * f.radius * len;
        let sq = f.squeeze(len);
        let want =
            lift * (1.0 / h - 1.0 / f.cutoff) + (sq.damping(h) - sq.damping(f.cutoff)) * (-rate);
        let got = l.normal_force(h, rate, u, len);
        assert!((got / want - 1.0).abs() < 1e-12, "{got} vs {want}");
        // the lift does not depend on the direction of the entrainment
        assert_eq!(l.normal_force(h, rate, -u, len), got);
        // the seed's bar forces (10–23 N) are what this film carries near the asperities
        let at_contact = l.normal_force(f.contact_film, 0.0, u, len);
        assert!(at_contact > 2.0 && at_contact < 10.0, "{at_contact}");
    }

    /// Continuous in the gap at the asperity film, at touch and at the reach; never negative;
    /// finite for extreme finite inputs.
    #[test]
    fn continuous_non_negative_and_finite() {
        let l = lubricated();
        let law = BarForceLaw::Lubricated(l);
        let hc = l.film.contact_film;
        let eps = 1e-15;
        for (rate, u) in [
            (-0.1, 19.0),
            (0.0, 19.0),
            (0.3, 19.0),
            (-0.1, 0.0),
            (0.05, 2.0),
        ] {
            for g in [hc, 0.0, law.reach()] {
                let (a, b) = (
                    law.normal_force(g - eps, rate, u, 5e-3),
                    law.normal_force(g + eps, rate, u, 5e-3),
                );
                // a step of 2 fm across the point moves the force by < 1 µN (forces are ~N)
                assert!((a - b).abs() <= 1e-6, "gap {g}: {a} vs {b}");
            }
            // between touch and the asperity film the film is frozen at h_c
            let frozen = law.normal_force(hc, rate, u, 5e-3);
            assert_eq!(law.normal_force(0.5 * hc, rate, u, 5e-3), frozen);
            assert_eq!(law.normal_force(law.reach() * 2.0, rate, u, 5e-3), 0.0);
        }
        let big = [-1e300, -1e3, -1.0, -1e-300, 0.0, 1e-300, 1.0, 1e300];
        for &g in &big {
            for &r in &big {
                for &u in &big {
                    for len in [0.0, 1e-300, 5e-3, 1e3] {
                        let f = law.normal_force(g, r, u, len);
                        assert!(f >= 0.0 && !f.is_nan(), "{g} {r} {u} {len}: {f}");
                    }
                }
            }
        }
        // separating fast: the cavitated film carries no tension
        assert_eq!(law.normal_force(5e-6, 10.0, 0.0, 5e-3), 0.0);
    }

    #[test]
    fn validation_rejects_bad_parameters() {
        let mut l = lubricated();
        assert!(BarForceLaw::Lubricated(l).validate().is_ok());
        l.film.cutoff = l.film.contact_film;
        assert!(BarForceLaw::Lubricated(l).validate().is_err());
        let e = ElasticBarLaw {
            reference_length: 0.0,
            ..elastic()
        };
        assert!(BarForceLaw::Elastic(e).validate().is_err());
    }
}
