//! Cage equilibrium (SPEC §5.5, seed 001): Φ(ε₀) ≡ T_S + T_sб + T_ts = 0 with every moment
//! signed along the bearing axis (the seed writes the resistance with a minus sign, ⚠ F-41).
//!
//! * Roller pushes: roller j at angle ψ_j exerts P_j e_θ (P_j from the roller's tangential
//!   balance) and the bar friction force −sgn(P_j) μ_s Q_bar e_r at its bar contact (a radial
//!   force at a point R_w ahead of / behind the roller centre). Moment
//!   T_S = Σ (P_j d_m/2 + μ_s Q_bar R_w) (seed 001: Σ(F_S (D_нр − D_wp)/2 − F_fs D_wp/2) — the
//!   seed's minus sign on the bar friction holds for rollers spinning against the cage, the
//!   vector form gives the sign for either sense);
//! * the reaction of the roller-end ↔ pocket film couple T_sc (a couple about an axis parallel
//!   to the bearing axis acts on the cage pocket walls; seed 001 does not list it in T_S, but
//!   without it the power balance of the bearing does not close);
//! * land friction (narrow journal bearing, [`crate::cage_land`]) with the pressing force
//!   F_RS = F_cs + √(F_SB² + F_SГ²), F_SB, F_SГ = Σ of the force components;
//!   ⚠ F-41: lever D_s1/2 (default) or the seed's D_s1 ([`crate::options::LandMomentArm`]);
//! * air–oil drag T_ts ([`crate::drag`]), opposing ω₀.

use crate::cage_land::{CageLandInput, CageLandOutput, QuasiStaticLandModel};
use crate::conditions::DragInputs;
use crate::drag::{CageDrag, CageDragGeometry, cage_drag};
use serde::Serialize;

/// Cage data used by the balance.
#[derive(Debug, Clone)]
pub struct CageSetup {
    /// Pitch radius d_m/2 (lever of the roller pushes), m.
    pub pitch_radius_m: f64,
    /// Roller radius (lever of the bar friction), m.
    pub roller_radius_m: f64,
    /// Land contact (`None`: roller-guided cage or switched off).
    pub land: Option<LandSetup>,
    /// Drag geometry.
    pub drag: CageDragGeometry,
    /// Drag inputs.
    pub drag_inputs: DragInputs,
    /// Oil density and viscosity at the mixture temperature.
    pub mixture_oil: (f64, f64),
    /// Lever factor of the land moment: 1 (D_s1/2) or 2 (seed's D_s1).
    pub land_arm_factor: f64,
}

/// Land data.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LandSetup {
    /// Film radius, m.
    pub radius_m: f64,
    /// Rail width, m.
    pub rail_width_m: f64,
    /// Number of rails.
    pub rails: u32,
    /// Radial clearance, m.
    pub radial_clearance_m: f64,
    /// Viscosity at the land ring's temperature, Pa·s.
    pub viscosity_pa_s: f64,
    /// The land is on the outer ring.
    pub outer_ring: bool,
    /// Cage mass, kg.
    pub cage_mass_kg: f64,
}

/// What one roller contributes to the cage.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollerOnCage {
    /// Angle ψ_j from the load direction, rad.
    pub azimuth_rad: f64,
    /// P_j, N.
    pub push_n: f64,
    /// Signed μ_s Q_bar (bar friction "moment force"), N.
    pub bar_friction_n: f64,
    /// Reaction of the roller-end ↔ pocket film couple T_sc on the cage, N·m.
    pub pocket_couple_n_m: f64,
}

/// Moments and forces on the cage at one cage speed.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct CageBalance {
    /// T_S: moment of the roller pushes and bar friction, N·m.
    pub roller_torque_n_m: f64,
    /// Land friction moment T_sб (signed), N·m.
    pub land_torque_n_m: f64,
    /// Air–oil drag moment T_ts (signed), N·m.
    pub drag_torque_n_m: f64,
    /// Φ = sum of the above, N·m.
    pub residual_n_m: f64,
    /// Sum of the magnitudes of all moments (scale of Φ), N·m.
    pub scale_n_m: f64,
    /// F_SB, F_SГ: components of the roller force resultant on the cage (x, y), N.
    pub roller_force_n: [f64; 2],
    /// Pressing force on the land F_RS, N.
    pub pressing_force_n: f64,
    /// Cage eccentricity ratio on the land.
    pub eccentricity_ratio: f64,
    /// Minimum land film, m.
    pub land_min_film_m: f64,
    /// Land friction coefficient f = |T|/(R F_RS).
    pub land_friction_coefficient: f64,
    /// Land power, W.
    pub land_power_w: f64,
    /// Land hydrodynamic capacity exceeded.
    pub land_saturated: bool,
    /// Drag details.
    pub drag: CageDrag,
}

/// Cage balance at cage speed `cage_speed` with land ring speed `land_speed` and the roller
/// force resultant turning at `load_speed` (the speed of the radial-load direction).
pub fn cage_balance(
    setup: &CageSetup,
    rollers: &[RollerOnCage],
    cage_speed: f64,
    land_speed: f64,
    load_speed: f64,
    land_model: &dyn QuasiStaticLandModel,
) -> CageBalance {
    let (mut fx, mut fy, mut t_s, mut scale) = (0.0, 0.0, 0.0, 0.0);
    for r in rollers {
        let (s, c) = r.azimuth_rad.sin_cos();
        // e_r = (sin ψ, cos ψ), e_θ = (cos ψ, −sin ψ)
        let fr = -r.push_n.signum() * r.bar_friction_n;
        fx += r.push_n * c + fr * s;
        fy += -r.push_n * s + fr * c;
        let tp = r.push_n * setup.pitch_radius_m;
        let tb = r.bar_friction_n * setup.roller_radius_m;
        t_s += tp + tb + r.pocket_couple_n_m;
        scale += tp.abs() + tb.abs() + r.pocket_couple_n_m.abs();
    }
    let resultant = fx.hypot(fy);
    let land: CageLandOutput = match &setup.land {
        Some(l) => land_model.evaluate(&CageLandInput {
            land_radius_m: l.radius_m,
            rail_width_m: l.rail_width_m,
            rails: l.rails,
            radial_clearance_m: l.radial_clearance_m,
            viscosity_pa_s: l.viscosity_pa_s,
            cage_speed_rad_s: cage_speed,
            land_speed_rad_s: land_speed,
            load_speed_rad_s: load_speed,
            roller_force_n: resultant,
            cage_mass_kg: l.cage_mass_kg,
        }),
        None => CageLandOutput {
            pressing_force_n: resultant,
            ..CageLandOutput::default()
        },
    };
    let t_land = land.torque_on_cage_n_m * setup.land_arm_factor;
    let drag = cage_drag(
        &setup.drag,
        &setup.drag_inputs,
        cage_speed,
        setup.mixture_oil.0,
        setup.mixture_oil.1,
    );
    let residual = t_s + t_land + drag.torque_n_m;
    CageBalance {
        roller_torque_n_m: t_s,
        land_torque_n_m: t_land,
        drag_torque_n_m: drag.torque_n_m,
        residual_n_m: residual,
        scale_n_m: scale + t_land.abs() + drag.torque_n_m.abs() + 1e-12,
        roller_force_n: [fx, fy],
        pressing_force_n: land.pressing_force_n,
        eccentricity_ratio: land.eccentricity_ratio,
        land_min_film_m: land.min_film_m,
        land_friction_coefficient: land.friction_coefficient,
        land_power_w: land.power_w * setup.land_arm_factor,
        land_saturated: land.saturated,
        drag,
    }
}
