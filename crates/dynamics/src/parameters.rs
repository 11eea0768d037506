//! Contact parameters of SPEC Table 2.1 (seed 000) per contact pair, with documented defaults.
//!
//! The seed gives no numbers for any of them (⚠ F-21); every default below is a proposal with
//! its reasoning. Pair indices follow SPEC §3.2: 1 inner ring, 2 outer ring, 3 roller slices,
//! 4 cage (pairs 13, 23 raceways; 34 roller–cage bar; 14 cage–guiding land), 5 roller ends,
//! 6 ribs (pair 56 roller ends ↔ ribs, pair 54 roller ends ↔ cage pocket faces).

use crate::error::DynError;
use rolldyn_contact::bar_force::{BarFilm, BarForceLaw, ElasticBarLaw, LubricatedBarLaw};
use rolldyn_contact::damping::TwoLevelFriction;
use rolldyn_contact::slices::SliceLaw;
use rolldyn_geometry::CylindricalRollerBearing;

/// Parameters of a compliant contact `F_n = K_p δ^n + STEP(δ, 0, 0, d, C_h)·δ̇` (clamped ≥ 0,
/// SPEC §3.3 / §3.4 with ⚠ F-18) with the two-level friction law (SPEC §3.4, ⚠ F-19/F-20).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairParameters {
    /// K_p, N/mⁿ (coefficient of the whole contact; split equally over its evaluation points).
    pub k_p: f64,
    /// n, exponent of the elastic part.
    pub exponent: f64,
    /// C_h, maximum damping coefficient, N·s/m.
    pub c_h: f64,
    /// d, penetration at which the damping reaches C_h, m.
    pub d: f64,
    /// μ_s, v_s, μ_d, v_d of the two-level friction law.
    pub friction: TwoLevelFriction,
}

impl PairParameters {
    /// Roller slice ↔ cage bar (pair 34). A law derived from the bearing's own bar, its line
    /// contact and the oil squeeze film is `rolldyn_contact::cage_bar::derive_for_bearing`
    /// (docs/theory.md §2.3.1; the example models carry theirs). Generic defaults:
    /// * `K_p = 2·10⁹ N/m^1.1`, `n = 1.1`: a steel line contact over the bar length (exponent of
    ///   the slice laws (2.3)/(2.4), ≈ 1.1) in series with bar bending (a 4 × 10 × 11 mm steel bar
    ///   clamped at both ends: ≈ 1.6·10⁹ N/m); gives 500 N at 1 µm, stiffness 5.5·10⁸ N/m.
    /// * `C_h = 500 N·s/m`, `d = 1 µm`: ≈ 10 % of critical damping of a 15 g roller on that
    ///   stiffness (ADAMS IMPACT practice: d = 0.001 mm).
    /// * friction `μ_s = 0.02`, `μ_d = 0.01`, `v_s = 5 mm/s`, `v_d = 50 mm/s`: SPEC §3.3 gives
    ///   0.00075…0.02 for the lubricated cage contacts; the regularisation band is wide enough
    ///   to keep the tangential "damping" `μ_s F_n/v_s` below the contact stiffness limit.
    pub fn roller_cage_default() -> Self {
        Self {
            k_p: 2e9,
            exponent: 1.1,
            c_h: 500.0,
            d: 1e-6,
            friction: TwoLevelFriction {
                mu_static: 0.02,
                mu_dynamic: 0.01,
                v_static: 5e-3,
                v_dynamic: 5e-2,
            },
        }
    }

    /// Cage ↔ guiding land (pair 14). Defaults:
    /// * `K_p = 1·10⁹ N/m^1.1`, `n = 1.1`: near-conformal steel contact of the cage bore on the
    ///   land (large contact length, so stiffer than a cage bar but the cage ring is compliant).
    /// * `C_h = 2000 N·s/m`, `d = 1 µm`: ≈ 5 % of critical damping for a ~0.3 kg cage.
    /// * friction `μ_s = 0.02`, `μ_d = 0.01`, `v_s = 10 mm/s`, `v_d = 100 mm/s` (SPEC §3.3:
    ///   hydrodynamic, 0.00075…0.02).
    pub fn cage_land_default() -> Self {
        Self {
            k_p: 1e9,
            exponent: 1.1,
            c_h: 2000.0,
            d: 1e-6,
            friction: TwoLevelFriction {
                mu_static: 0.02,
                mu_dynamic: 0.01,
                v_static: 1e-2,
                v_dynamic: 1e-1,
            },
        }
    }

    /// Frictionless, undamped copy (energy-conservation checks).
    pub fn conservative(mut self) -> Self {
        self.c_h = 0.0;
        self.friction.mu_static = 0.0;
        self.friction.mu_dynamic = 0.0;
        self
    }

    pub(crate) fn validate(&self, what: &str) -> Result<(), DynError> {
        let ok = self.k_p > 0.0
            && self.k_p.is_finite()
            && self.exponent >= 1.0
            && self.exponent.is_finite()
            && self.c_h >= 0.0
            && self.c_h.is_finite()
            && self.d > 0.0
            && self.d.is_finite();
        if !ok {
            return Err(DynError::InvalidInput(format!(
                "{what}: need K_p > 0, n ≥ 1, C_h ≥ 0, d > 0 (all finite)"
            )));
        }
        TwoLevelFriction::new(
            self.friction.mu_static,
            self.friction.mu_dynamic,
            self.friction.v_static,
            self.friction.v_dynamic,
        )
        .map_err(|e| DynError::InvalidInput(format!("{what}: {e}")))?;
        Ok(())
    }
}

/// Friction law of a roller-end contact (SPEC §3.4, ⚠ F-23, §6.7).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum EndFriction {
    /// Constant boundary friction `μ_s = μ_d` of [`PairParameters::friction`] (default 0.065,
    /// seed 000 §2.1), regularised to 0 below `v_s`.
    #[default]
    Boundary,
    /// Kragelsky μ_bd(s) of seed 000 (2.10) at the relative slip `s = v/u` of the end contact
    /// (the F-23 switch; → 0.1 at large slip).
    Kragelsky,
    /// EHL point-contact traction of the inner-raceway traction model while the contact spot
    /// (radius `√(R δ)`) stays inside the overlap of end face and rib face (SPEC §6.7), boundary
    /// friction otherwise. Needs a finite reduced radius, i.e. a spherical roller end or a
    /// convex rib; flat–flat pairs always run in boundary friction. Ribs only (cage pocket
    /// faces use the boundary law).
    Ehl,
}

/// Roller end ↔ rib (pair 56) or roller end ↔ cage pocket face (pair 54): power law with STEP
/// damping (SPEC §3.3) and the friction law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollerEndParameters {
    /// Switch (false: the contact is not evaluated — comparison runs).
    pub enabled: bool,
    /// K_p, n, C_h, d and the regularised boundary friction (μ_s = μ_d = μ).
    pub contact: PairParameters,
    /// Friction law.
    pub friction: EndFriction,
}

impl RollerEndParameters {
    /// Roller end ↔ rib (pair 56) for a bearing. Defaults (⚠ F-21: the seed's FE curves of
    /// Fig. 2.5 have no numbers):
    /// * `n = 1.5`, `K_p = (4/3) E* √R_e` — Hertz point contact of the roller edge (corner of
    ///   radius `r_b` = roller edge break, floored at 0.1 mm, round the end circle of radius
    ///   `r_e = D_w/2 − r_b`) on a flat steel rib face, `R_e = √(r_b r_e)`, `1/E* = (1−ν₁²)/E₁ +
    ///   (1−ν₂²)/E₂` of roller and inner ring. A skewed or tilted flat end always touches with its
    ///   edge (seed Fig. 2.5: non-linear as soon as the roller rotates); 2002834 gives
    ///   5.8·10⁹ N/m^1.5 (12 N at 1.5 µm, stiffness 1.2·10⁷ N/m — two orders below the raceway,
    ///   so the rib never limits the explicit step).
    /// * `C_h = 100 N·s/m`, `d = 1 µm`: ≈ 10 % of critical for a 15 g roller at 5 µm approach.
    /// * friction: constant 0.065 (seed 000 §2.1 / SPEC Table "contact pairs", row 56),
    ///   regularised over `v_s = 5 mm/s` (`v_d = 10 mm/s`); sliding at the ends is of the order
    ///   of m/s, so the regularisation only acts at standstill.
    pub fn rib_default(bearing: &CylindricalRollerBearing) -> Self {
        let r = &bearing.roller;
        let rb = r.edge_break.max(1e-4);
        let re = (0.5 * r.diameter - rb).max(rb);
        let e_star = 1.0 / (r.material.compliance() + bearing.inner_ring.material.compliance());
        Self {
            enabled: true,
            contact: PairParameters {
                k_p: 4.0 / 3.0 * e_star * (rb * re).sqrt().sqrt(),
                exponent: 1.5,
                c_h: 100.0,
                d: 1e-6,
                friction: TwoLevelFriction {
                    mu_static: 0.065,
                    mu_dynamic: 0.065,
                    v_static: 5e-3,
                    v_dynamic: 1e-2,
                },
            },
            friction: EndFriction::Boundary,
        }
    }

    /// Roller end ↔ cage pocket face (pair 54). Defaults as [`Self::rib_default`] with the cage
    /// material, `K_p` halved for the bending of the cage side ring that carries the pocket face
    /// (a guess: no FE data, ⚠ F-21); two-level friction with `μ_s = μ_d = 0.065` (seed: boundary,
    /// constant 0.065).
    pub fn pocket_default(bearing: &CylindricalRollerBearing) -> Self {
        let mut p = Self::rib_default(bearing);
        let r = &bearing.roller;
        let rb = r.edge_break.max(1e-4);
        let re = (0.5 * r.diameter - rb).max(rb);
        let cage_c = bearing
            .cage
            .as_ref()
            .map(|c| c.material.compliance())
            .unwrap_or(r.material.compliance());
        let e_star = 1.0 / (r.material.compliance() + cage_c);
        p.contact.k_p = 0.5 * 4.0 / 3.0 * e_star * (rb * re).sqrt().sqrt();
        p
    }

    /// Frictionless, undamped copy.
    pub fn conservative(mut self) -> Self {
        self.contact = self.contact.conservative();
        self.friction = EndFriction::Boundary;
        self
    }
}

/// Parameters of the roller-slice ↔ raceway contacts (pairs 13, 23).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RacewayParameters {
    /// Slice force–deflection law (SPEC §2.1). Default: seed 000 eq. (2.3) for the inner and
    /// (2.4) for the outer ring, built from the bearing geometry.
    pub law: SliceLaw,
    /// Maximum damping of the whole roller–raceway contact, N·s/m; split over the slices in
    /// proportion to their length (SPEC §2.2, eqs. (2.5)–(2.8) with ⚠ F-16/F-17). Default
    /// 400 N·s/m ≈ 5 % of critical for a 15 g roller on a ≈ 10⁹ N/m line contact — oil-film
    /// squeeze damping of EHL line contacts is of this order, and it removes the start transient
    /// within a few roller–raceway periods without affecting the steady forces.
    pub damping_n_s_m: f64,
    /// Critical approach δ* of the damping ramp, m. Default 1 µm (ADAMS IMPACT practice, the
    /// order of a working slice approach).
    pub damping_ramp_m: f64,
}

/// All contact parameters of a cylindrical roller bearing (SPEC Table 2.1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactParameters {
    /// Pair 13, roller slices ↔ inner raceway.
    pub inner_raceway: RacewayParameters,
    /// Pair 23, roller slices ↔ outer raceway.
    pub outer_raceway: RacewayParameters,
    /// Pair 34, roller ↔ cage bar.
    pub roller_cage: PairParameters,
    /// Force law of pair 34: `None` = the elastic law of [`Self::roller_cage`] (default);
    /// `Some(film)` = the oil film between roller and bar down to its asperity film, the
    /// elastic law below it (docs/theory.md §2.3.1); composed by [`Self::roller_cage_law`].
    pub roller_cage_film: Option<BarFilm>,
    /// Pair 14 (or the outer-ring land), cage ↔ guiding land.
    pub cage_land: PairParameters,
    /// Pair 56, roller ends ↔ ring ribs (inner and outer ring, whichever have ribs).
    pub roller_end_rib: RollerEndParameters,
    /// Pair 54, roller ends ↔ cage pocket faces.
    pub roller_end_cage: RollerEndParameters,
}

impl ContactParameters {
    /// Defaults for a bearing: seed 000 slice laws (2.3)/(2.4) with the bearing's pitch
    /// diameter, ring wall and outside diameter, roller material; pair defaults of
    /// [`PairParameters`].
    pub fn for_bearing(bearing: &CylindricalRollerBearing) -> Self {
        let mat = &bearing.roller.material;
        let dm = bearing.pitch_diameter();
        let inner = SliceLaw::InnerRing {
            pitch_diameter: dm,
            youngs_modulus: mat.youngs_modulus,
            poisson_ratio: mat.poisson_ratio,
        };
        let outer = SliceLaw::OuterRing {
            ring_wall_thickness: bearing.outer_ring.wall_thickness(),
            outside_diameter: bearing.outer_ring.body_diameter,
            pitch_diameter: dm,
            youngs_modulus: mat.youngs_modulus,
            poisson_ratio: mat.poisson_ratio,
        };
        Self {
            inner_raceway: RacewayParameters {
                law: inner,
                damping_n_s_m: 400.0,
                damping_ramp_m: 1e-6,
            },
            outer_raceway: RacewayParameters {
                law: outer,
                damping_n_s_m: 400.0,
                damping_ramp_m: 1e-6,
            },
            roller_cage: PairParameters::roller_cage_default(),
            roller_cage_film: None,
            cage_land: PairParameters::cage_land_default(),
            roller_end_rib: RollerEndParameters::rib_default(bearing),
            roller_end_cage: RollerEndParameters::pocket_default(bearing),
        }
    }

    /// The pair-34 force law per roller slice: [`Self::roller_cage`]'s `K_p`, `n`, `C_h`, `d`
    /// for the whole contact of `reference_length` (m; the bar contact length,
    /// `rolldyn_contact::bar_force::bar_contact_length`), with the film when there is one.
    pub fn roller_cage_law(&self, reference_length: f64) -> BarForceLaw {
        let p = &self.roller_cage;
        let elastic = ElasticBarLaw {
            k_p: p.k_p,
            exponent: p.exponent,
            c_h: p.c_h,
            d: p.d,
            reference_length,
        };
        match self.roller_cage_film {
            None => BarForceLaw::Elastic(elastic),
            Some(film) => BarForceLaw::Lubricated(LubricatedBarLaw { elastic, film }),
        }
    }

    /// Frictionless and undamped copy of all non-raceway pairs, undamped raceways (energy
    /// checks; raceway friction is set through the traction models).
    pub fn conservative(mut self) -> Self {
        self.inner_raceway.damping_n_s_m = 0.0;
        self.outer_raceway.damping_n_s_m = 0.0;
        self.roller_cage = self.roller_cage.conservative();
        self.roller_cage_film = None;
        self.cage_land = self.cage_land.conservative();
        self.roller_end_rib = self.roller_end_rib.conservative();
        self.roller_end_cage = self.roller_end_cage.conservative();
        self
    }

    pub(crate) fn validate(&self) -> Result<(), DynError> {
        for (what, r) in [
            ("inner raceway", &self.inner_raceway),
            ("outer raceway", &self.outer_raceway),
        ] {
            r.law
                .validate()
                .map_err(|e| DynError::InvalidInput(format!("{what} slice law: {e}")))?;
            if !(r.damping_n_s_m >= 0.0 && r.damping_n_s_m.is_finite()) {
                return Err(DynError::InvalidInput(format!(
                    "{what}: damping must be finite and ≥ 0"
                )));
            }
            if !(r.damping_ramp_m > 0.0 && r.damping_ramp_m.is_finite()) {
                return Err(DynError::InvalidInput(format!(
                    "{what}: damping ramp δ* must be > 0"
                )));
            }
        }
        self.roller_cage.validate("roller–cage (34)")?;
        self.roller_cage_law(1.0)
            .validate()
            .map_err(|e| DynError::InvalidInput(format!("roller–cage (34): {e}")))?;
        self.cage_land.validate("cage–land (14)")?;
        self.roller_end_rib
            .contact
            .validate("roller end–rib (56)")?;
        self.roller_end_cage
            .contact
            .validate("roller end–cage pocket (54)")?;
        Ok(())
    }
}
