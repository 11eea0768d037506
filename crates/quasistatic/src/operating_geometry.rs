//! Operating geometry (SPEC §5.2): radial clearance in operation from the mounting clearance,
//! the interference fits (Lamé thick-cylinder theory with ring-thickness factors), thermal
//! expansion of rings, rollers, shaft, housing and cage, and centrifugal growth of the rotating
//! rings, shaft/housing and cage; operating cage floating clearance and roller–rib clearance.
//!
//! ⚠ F-43: seed 001 names these effects but gives no formula; the standard forms used here
//! (not in the seeds) are
//! * free thermal growth Δd = α d (T − T_asm) of each part at its own temperature;
//! * free centrifugal growth of a rotating annulus a ≤ r ≤ b (plane stress, Timoshenko):
//!   u(r) = ρω²/(8E) [(3+ν)(1−ν)(a²+b²) r + (3+ν)(1+ν) a²b²/r − (1−ν²) r³];
//! * fit pressure from the **operating** interference (mounting interference corrected by the
//!   differential thermal and centrifugal growth of the mating surfaces, as seed 001 requires:
//!   "the fits themselves depend on thermal and centrifugal expansion"), Lamé:
//!   p = δ / (b [(1/E_o)((c²+b²)/(c²−b²) + ν_o) + (1/E_i)((b²+a²)/(b²−a²) − ν_i)]),
//!   δ = I/2, inner member a…b, outer member b…c; the raceway of an inner ring (outer surface
//!   c) grows by Δd = 4 p b² c / (E (c² − b²)), the raceway of an outer ring (bore a under
//!   external pressure at b) shrinks by ΔD = 4 p b² a / (E (b² − a²)). For equal materials and
//!   a solid shaft this is the ring-thickness factor Δd_i = I·d/d_i of Harris.
//!
//! Every contribution is reported separately ([`ClearanceContributions`]); the growth is
//! superposed (free thermal + free centrifugal + fit), as is usual for bearing clearances.

use crate::conditions::{PartMaterial, QuasiStaticConditions};
use rolldyn_geometry::{CageGuidance, CylindricalRollerBearing, Material};
use serde::Serialize;

/// Contributions to the diametral radial clearance in operation, m (positive opens the
/// clearance). `operating_m` is their sum.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ClearanceContributions {
    /// Mounting (assembly) radial clearance G_r (diametral): the bearing model's, or, when the
    /// model gives the operating clearance (`Clearance::radial_is_operating`), the one it implies.
    pub mounting_m: f64,
    /// Inner-ring raceway expansion by the shaft fit (−Δd_i).
    pub inner_fit_m: f64,
    /// Outer-ring raceway contraction by the housing fit (+ΔD_o, ≤ 0).
    pub outer_fit_m: f64,
    /// Thermal growth of the inner raceway (−α d_i ΔT_i).
    pub inner_ring_thermal_m: f64,
    /// Thermal growth of the outer raceway (+α D_o ΔT_o).
    pub outer_ring_thermal_m: f64,
    /// Thermal growth of the rollers (−2 α D_w ΔT_w).
    pub roller_thermal_m: f64,
    /// Centrifugal growth of the inner raceway (−Δd_i).
    pub inner_ring_centrifugal_m: f64,
    /// Centrifugal growth of the outer raceway (+ΔD_o).
    pub outer_ring_centrifugal_m: f64,
    /// Operating diametral clearance (sum).
    pub operating_m: f64,
}

/// Fit state of one ring.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FitState {
    /// Mounting diametral interference, m.
    pub mounting_interference_m: f64,
    /// Interference change by differential thermal growth, m.
    pub thermal_change_m: f64,
    /// Interference change by differential centrifugal growth, m.
    pub centrifugal_change_m: f64,
    /// Operating interference (≤ 0 → the fit is loose), m.
    pub operating_interference_m: f64,
    /// Contact pressure of the fit, Pa.
    pub pressure_pa: f64,
    /// Diametral change of the raceway caused by the fit, m.
    pub raceway_change_m: f64,
}

/// Operating floating clearance of the cage on its guiding land (diametral), m.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CageClearance {
    /// Mounting floating clearance g_пп of the model.
    pub mounting_m: f64,
    /// Growth of the land diameter (thermal + centrifugal + fit of its ring), m.
    pub land_growth_m: f64,
    /// Thermal growth of the cage centring diameter, m.
    pub cage_thermal_m: f64,
    /// Centrifugal growth of the cage centring diameter at the estimated cage speed, m.
    pub cage_centrifugal_m: f64,
    /// Operating floating clearance (diametral), m.
    pub operating_m: f64,
    /// Operating land diameter, m.
    pub land_diameter_m: f64,
}

/// Operating axial clearance, m.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AxialClearance {
    /// Mounting value, m.
    pub mounting_m: f64,
    /// Thermal growth of the ring rib spacing or of the cage pocket, m.
    pub housing_part_thermal_m: f64,
    /// Thermal growth of the roller length (subtracted), m.
    pub roller_thermal_m: f64,
    /// Operating value, m.
    pub operating_m: f64,
}

/// The bearing in operation (SPEC §5.2): diameters d_вр, D_нр, D_wp, d_m, clearances.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct OperatingGeometry {
    /// Radial clearance and its contributions.
    pub clearance: ClearanceContributions,
    /// Operating inner raceway diameter d_вр, m.
    pub inner_raceway_diameter_m: f64,
    /// Operating outer raceway diameter D_нр, m.
    pub outer_raceway_diameter_m: f64,
    /// Operating roller diameter D_wp, m.
    pub roller_diameter_m: f64,
    /// Operating roller length, m.
    pub roller_length_m: f64,
    /// Operating pitch diameter (d_вр + D_нр)/2, m.
    pub pitch_diameter_m: f64,
    /// Inner-ring fit on the shaft.
    pub inner_fit: FitState,
    /// Outer-ring fit in the housing.
    pub outer_fit: FitState,
    /// Cage floating clearance (`None` without a land-guided cage).
    pub cage: Option<CageClearance>,
    /// Roller–rib axial clearance Δ_бр (`None` without guiding ribs).
    pub roller_rib: Option<AxialClearance>,
    /// Roller-end ↔ cage-pocket axial clearance (`None` without a cage).
    pub pocket_end: Option<AxialClearance>,
    /// Diagnostics (loose fits, closed clearances).
    pub warnings: Vec<String>,
}

/// Free radial displacement at radius `r` of an annulus `a ≤ r ≤ b` rotating at `omega`
/// (plane stress; standard form, Timoshenko & Goodier).
pub fn centrifugal_displacement(
    r: f64,
    a: f64,
    b: f64,
    omega: f64,
    density: f64,
    youngs_modulus: f64,
    poisson: f64,
) -> f64 {
    if omega == 0.0 || r <= 0.0 {
        return 0.0;
    }
    let nu = poisson;
    let k = density * omega * omega / (8.0 * youngs_modulus);
    k * ((3.0 + nu) * (1.0 - nu) * (a * a + b * b) * r
        + (3.0 + nu) * (1.0 + nu) * a * a * b * b / r
        - (1.0 - nu * nu) * r * r * r)
}

/// Lamé fit pressure for diametral interference `interference` at the interface diameter
/// `2b`; inner member `a…b`, outer member `b…c` (`c = ∞` allowed).
pub fn fit_pressure(
    interference: f64,
    a: f64,
    b: f64,
    c: f64,
    inner: (f64, f64),
    outer: (f64, f64),
) -> f64 {
    if interference <= 0.0 {
        return 0.0;
    }
    let (e_i, nu_i) = inner;
    let (e_o, nu_o) = outer;
    let outer_term = if c.is_finite() {
        (c * c + b * b) / (c * c - b * b)
    } else {
        1.0
    };
    let inner_term = (b * b + a * a) / (b * b - a * a);
    0.5 * interference / (b * ((outer_term + nu_o) / e_o + (inner_term - nu_i) / e_i))
}

fn ring_material(m: &Material) -> (f64, f64) {
    (m.youngs_modulus, m.poisson_ratio)
}

fn part(m: &PartMaterial) -> (f64, f64) {
    (m.youngs_modulus, m.poisson_ratio)
}

/// Computes the operating geometry. `cage_speed_rad_s` is the (estimated) cage speed for the
/// cage's centrifugal growth (the solver passes the epicyclic speed: the cage's centrifugal
/// growth changes the floating clearance by < 1 µm in every seed case).
pub fn operating_geometry(
    bearing: &CylindricalRollerBearing,
    cond: &QuasiStaticConditions,
    cage_speed_rad_s: f64,
) -> OperatingGeometry {
    let t = &cond.temperatures;
    let ta = t.assembly;
    let ax = &cond.thermal_expansion;
    let mut warnings = Vec::new();
    let (wi, wo) = (cond.inner_speed_rad_s, cond.outer_speed_rad_s);

    let ir = &bearing.inner_ring;
    let or = &bearing.outer_ring;
    let d_i = ir.raceway_diameter;
    let d_bore = ir.body_diameter;
    let d_o = or.raceway_diameter;
    let d_out = or.body_diameter;
    let d_w = bearing.roller.diameter;

    // --- free thermal growth of the raceways and rollers
    let th_i = ax.inner_ring * d_i * (t.inner_ring - ta);
    let th_o = ax.outer_ring * d_o * (t.outer_ring - ta);
    let th_w = ax.rollers * d_w * (t.rollers - ta);

    // --- free centrifugal growth (ring alone)
    let (ei, nui) = ring_material(&ir.material);
    let (eo, nuo) = ring_material(&or.material);
    let cf_i = 2.0
        * centrifugal_displacement(
            0.5 * d_i,
            0.5 * d_bore,
            0.5 * d_i,
            wi,
            ir.material.density,
            ei,
            nui,
        );
    let cf_o = 2.0
        * centrifugal_displacement(
            0.5 * d_o,
            0.5 * d_o,
            0.5 * d_out,
            wo,
            or.material.density,
            eo,
            nuo,
        );

    let inner_fit = inner_ring_fit(bearing, cond, &mut warnings);
    let outer_fit = outer_ring_fit(bearing, cond, &mut warnings);

    let change =
        -inner_fit.raceway_change_m + outer_fit.raceway_change_m - th_i + th_o - 2.0 * th_w - cf_i
            + cf_o;
    // a clearance given as the operating one fixes the sum; the mounting clearance it implies
    // is what the contributions leave
    let g0 = if bearing.clearance.radial_is_operating {
        bearing.clearance.radial - change
    } else {
        bearing.clearance.radial
    };
    let contributions = ClearanceContributions {
        mounting_m: g0,
        inner_fit_m: -inner_fit.raceway_change_m,
        outer_fit_m: outer_fit.raceway_change_m,
        inner_ring_thermal_m: -th_i,
        outer_ring_thermal_m: th_o,
        roller_thermal_m: -2.0 * th_w,
        inner_ring_centrifugal_m: -cf_i,
        outer_ring_centrifugal_m: cf_o,
        operating_m: g0 + change,
    };
    let d_i_op = d_i + th_i + cf_i + inner_fit.raceway_change_m;
    let d_o_op = d_o + th_o + cf_o + outer_fit.raceway_change_m;
    let d_w_op = d_w + th_w;
    let l_op = bearing.roller.length * (1.0 + ax.rollers * (t.rollers - ta));

    let cage = cage_clearance(
        bearing,
        cond,
        (d_i_op - d_i, d_o_op - d_o),
        cage_speed_rad_s,
        &mut warnings,
    );
    let roller_rib = roller_rib_clearance(bearing, cond, &mut warnings);
    let pocket_end = pocket_end_clearance(bearing, cond);

    OperatingGeometry {
        clearance: contributions,
        inner_raceway_diameter_m: d_i_op,
        outer_raceway_diameter_m: d_o_op,
        roller_diameter_m: d_w_op,
        roller_length_m: l_op,
        pitch_diameter_m: 0.5 * (d_i_op + d_o_op),
        inner_fit,
        outer_fit,
        cage,
        roller_rib,
        pocket_end,
        warnings,
    }
}

/// Inner-ring fit on the shaft at the operating temperatures and speed (module docs, Lamé).
fn inner_ring_fit(
    bearing: &CylindricalRollerBearing,
    cond: &QuasiStaticConditions,
    warnings: &mut Vec<String>,
) -> FitState {
    let (t, ax, m) = (&cond.temperatures, &cond.thermal_expansion, &cond.mounting);
    let ta = t.assembly;
    let wi = cond.inner_speed_rad_s;
    let ir = &bearing.inner_ring;
    let (ei, nui) = ring_material(&ir.material);
    let d_bore = ir.body_diameter;
    let sm = &m.shaft_material;
    let (a_s, b_s, c_s) = (
        0.5 * m.shaft_bore_diameter_m,
        0.5 * d_bore,
        0.5 * ir.raceway_diameter,
    );

    let thermal =
        d_bore * (sm.thermal_expansion * (t.shaft - ta) - ax.inner_ring * (t.inner_ring - ta));
    let u_ring = centrifugal_displacement(b_s, b_s, c_s, wi, ir.material.density, ei, nui);
    let u_shaft = centrifugal_displacement(
        b_s,
        a_s,
        b_s,
        wi,
        sm.density,
        sm.youngs_modulus,
        sm.poisson_ratio,
    );
    let centrifugal = -2.0 * (u_ring - u_shaft);
    let op = m.shaft_interference_m + thermal + centrifugal;
    let p = fit_pressure(op, a_s, b_s, c_s, part(sm), (ei, nui));
    let growth = 4.0 * p * b_s * b_s * c_s / (ei * (c_s * c_s - b_s * b_s));
    let fit = FitState {
        mounting_interference_m: m.shaft_interference_m,
        thermal_change_m: thermal,
        centrifugal_change_m: centrifugal,
        operating_interference_m: op,
        pressure_pa: p,
        raceway_change_m: growth,
    };
    warn_if_fit_lost(&fit, "inner", warnings);
    fit
}

/// Outer-ring fit in the housing at the operating temperatures and speed (module docs, Lamé).
fn outer_ring_fit(
    bearing: &CylindricalRollerBearing,
    cond: &QuasiStaticConditions,
    warnings: &mut Vec<String>,
) -> FitState {
    let (t, ax, m) = (&cond.temperatures, &cond.thermal_expansion, &cond.mounting);
    let ta = t.assembly;
    let wo = cond.outer_speed_rad_s;
    let or = &bearing.outer_ring;
    let (eo, nuo) = ring_material(&or.material);
    let d_out = or.body_diameter;
    let hm = &m.housing_material;
    let (a_h, b_h) = (0.5 * or.raceway_diameter, 0.5 * d_out);
    let c_h = m
        .housing_outside_diameter_m
        .map_or(f64::INFINITY, |d| 0.5 * d);

    let thermal =
        d_out * (ax.outer_ring * (t.outer_ring - ta) - hm.thermal_expansion * (t.housing - ta));
    let u_ring = centrifugal_displacement(b_h, a_h, b_h, wo, or.material.density, eo, nuo);
    let u_housing = if c_h.is_finite() {
        centrifugal_displacement(
            b_h,
            b_h,
            c_h,
            wo,
            hm.density,
            hm.youngs_modulus,
            hm.poisson_ratio,
        )
    } else {
        0.0
    };
    let centrifugal = -2.0 * (u_housing - u_ring);
    let op = m.housing_interference_m + thermal + centrifugal;
    let p = fit_pressure(op, a_h, b_h, c_h, (eo, nuo), part(hm));
    let change = -4.0 * p * b_h * b_h * a_h / (eo * (b_h * b_h - a_h * a_h));
    let fit = FitState {
        mounting_interference_m: m.housing_interference_m,
        thermal_change_m: thermal,
        centrifugal_change_m: centrifugal,
        operating_interference_m: op,
        pressure_pa: p,
        raceway_change_m: change,
    };
    warn_if_fit_lost(&fit, "outer", warnings);
    fit
}

/// Warns when a mounting interference is lost in operation.
fn warn_if_fit_lost(fit: &FitState, ring: &str, warnings: &mut Vec<String>) {
    if fit.mounting_interference_m > 0.0 && fit.operating_interference_m <= 0.0 {
        warnings.push(format!(
            "{ring}-ring fit lost in operation: interference {:.1} µm → {:.1} µm",
            fit.mounting_interference_m * 1e6,
            fit.operating_interference_m * 1e6
        ));
    }
}

/// Operating cage floating clearance; `raceway_growth` is the operating growth of the inner
/// and outer raceway diameters, m.
fn cage_clearance(
    bearing: &CylindricalRollerBearing,
    cond: &QuasiStaticConditions,
    raceway_growth: (f64, f64),
    cage_speed_rad_s: f64,
    warnings: &mut Vec<String>,
) -> Option<CageClearance> {
    let (t, ax) = (&cond.temperatures, &cond.thermal_expansion);
    let ta = t.assembly;
    let (d_i, d_o) = (
        bearing.inner_ring.raceway_diameter,
        bearing.outer_ring.raceway_diameter,
    );
    bearing.cage.as_ref().and_then(|c| {
        let land = c.land_diameter()?;
        let (ring_growth, ring_d) = match c.guidance {
            CageGuidance::InnerLand => (raceway_growth.0, d_i),
            _ => (raceway_growth.1, d_o),
        };
        // land on the same ring: its diameter grows in proportion to the raceway's
        let land_growth = ring_growth * land / ring_d;
        let centring = match c.guidance {
            CageGuidance::InnerLand => c.inner_diameter,
            _ => c.outer_diameter,
        };
        let cage_th = ax.cage * centring * (t.cage - ta);
        let (ec, nuc) = ring_material(&c.material);
        let cage_cf = 2.0
            * centrifugal_displacement(
                0.5 * centring,
                0.5 * c.inner_diameter,
                0.5 * c.outer_diameter,
                cage_speed_rad_s,
                c.material.density,
                ec,
                nuc,
            );
        let mut op = match c.guidance {
            CageGuidance::InnerLand => c.floating_clearance + cage_th + cage_cf - land_growth,
            _ => c.floating_clearance + land_growth - cage_th - cage_cf,
        };
        if op <= 0.0 {
            warnings.push(format!(
                "cage floating clearance closes in operation ({:.1} µm): 1 µm used",
                op * 1e6
            ));
            op = 1e-6;
        }
        Some(CageClearance {
            mounting_m: c.floating_clearance,
            land_growth_m: land_growth,
            cage_thermal_m: cage_th,
            cage_centrifugal_m: cage_cf,
            operating_m: op,
            land_diameter_m: land + land_growth,
        })
    })
}

/// Roller–rib axial clearance in operation, on the ring that carries two ribs.
fn roller_rib_clearance(
    bearing: &CylindricalRollerBearing,
    cond: &QuasiStaticConditions,
    warnings: &mut Vec<String>,
) -> Option<AxialClearance> {
    let (t, ax) = (&cond.temperatures, &cond.thermal_expansion);
    let ta = t.assembly;
    let (ir, or) = (&bearing.inner_ring, &bearing.outer_ring);
    bearing.roller_rib_axial_clearance().map(|c0| {
        let (ring_alpha, ring_t) = if or.rib_spacing.is_some() && ir.rib_spacing.is_none() {
            (ax.outer_ring, t.outer_ring)
        } else {
            (ax.inner_ring, t.inner_ring)
        };
        let spacing = bearing.roller.length + c0;
        let ring_th = ring_alpha * spacing * (ring_t - ta);
        let roller_th = ax.rollers * bearing.roller.length * (t.rollers - ta);
        let mut op = c0 + ring_th - roller_th;
        if op <= 0.0 {
            warnings.push(format!(
                "roller–rib axial clearance closes in operation ({:.1} µm): 1 µm used",
                op * 1e6
            ));
            op = 1e-6;
        }
        AxialClearance {
            mounting_m: c0,
            housing_part_thermal_m: ring_th,
            roller_thermal_m: roller_th,
            operating_m: op,
        }
    })
}

/// Roller–pocket axial clearance in operation (at least 1 µm).
fn pocket_end_clearance(
    bearing: &CylindricalRollerBearing,
    cond: &QuasiStaticConditions,
) -> Option<AxialClearance> {
    let (t, ax) = (&cond.temperatures, &cond.thermal_expansion);
    let ta = t.assembly;
    bearing.cage.as_ref().map(|c| {
        let c0 = c.pocket.axial - bearing.roller.length;
        let cage_th = ax.cage * c.pocket.axial * (t.cage - ta);
        let roller_th = ax.rollers * bearing.roller.length * (t.rollers - ta);
        AxialClearance {
            mounting_m: c0,
            housing_part_thermal_m: cage_th,
            roller_thermal_m: roller_th,
            operating_m: (c0 + cage_th - roller_th).max(1e-6),
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solid_disc_centrifugal_matches_closed_form() {
        // solid disc, rim displacement u(b) = ρω²b³(1 − ν)/(4E)
        let (rho, e, nu, w, b) = (7830.0, 208e9, 0.3, 1000.0, 0.05);
        let u = centrifugal_displacement(b, 0.0, b, w, rho, e, nu);
        let expected = rho * w * w * b * b * b * (1.0 - nu) / (4.0 * e);
        assert!((u / expected - 1.0).abs() < 1e-12);
    }

    #[test]
    fn thin_ring_centrifugal_limit() {
        // thin ring: u = ρω²r³/E
        let (rho, e, nu, w, r) = (7830.0, 208e9, 0.3, 1000.0, 0.05);
        let u = centrifugal_displacement(r, r * 0.9999, r * 1.0001, w, rho, e, nu);
        assert!((u / (rho * w * w * r * r * r / e) - 1.0).abs() < 1e-3);
    }

    #[test]
    fn fit_factor_solid_shaft_equal_materials() {
        // Harris: Δd_i = I d / d_i for a solid shaft of the ring's material
        let (i, d, di) = (20e-6, 0.05, 0.065);
        let (e, nu) = (208e9, 0.3);
        let p = fit_pressure(i, 0.0, 0.5 * d, 0.5 * di, (e, nu), (e, nu));
        let (b, c) = (0.5 * d, 0.5 * di);
        let growth = 4.0 * p * b * b * c / (e * (c * c - b * b));
        assert!((growth / (i * d / di) - 1.0).abs() < 1e-12);
    }
}
