//! The precomputed description of a double-row tapered run: both rows' geometry, the slices of
//! a roller, contact laws and parameters, masses, operating conditions, traction models.

use super::geometry::{RowGeometry, row_geometry};
use crate::conditions::OperatingConditions;
use crate::ends::{EndGeometry, film_limit_approach};
use crate::error::DynError;
use crate::parameters::{EndFriction, PairParameters, RacewayParameters, RollerEndParameters};
use rolldyn_contact::damping::{SliceDamping, TwoLevelFriction};
use rolldyn_contact::hertz::{
    ContactCurvatures, EllipticalMethod, EllipticalStiffness, LineApproachModel, LineContact,
    elliptical_contact,
};
use rolldyn_contact::slices::tapered_raceway_laws;
use rolldyn_geometry::{DoubleRowTaperedBearing, MassProperties};
use rolldyn_lubrication::TractionModel;

/// Contact parameters of the tapered bearing (seed 000 §3.2 gives only the roller–cage friction
/// 0.06 and that the end–rib compliance came from FE; the rest are documented proposals).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TaperedParameters {
    /// Roller slices ↔ cone raceway: slice law (2.3) with d_m, damping of the whole line
    /// contact 1500 N·s/m (≈ 5 % of critical for a 0.15 kg roller on the ≈ 10⁹ N/m stiffness
    /// of a 10 kN line contact — the 2002834 value scaled by √(m k)).
    pub cone: RacewayParameters,
    /// Roller slices ↔ cup raceway: slice law (2.4) with the cup wall, damping as the cone.
    pub cup: RacewayParameters,
    /// Roller ↔ polyamide cage bar edges: Palmgren's line law rescaled to the reduced modulus
    /// of steel on the cage material (PA66-GF25 of the example: E' = 6.7·10⁹ Pa) over a 10 mm
    /// edge (K = 4.0·10⁷ N/m^1.11 for the example), μ of the cage (0.06, seed 000 §3.2.1)
    /// constant, regularised over 5 mm/s.
    pub roller_cage: PairParameters,
    /// Roller large end ↔ large rib: Hertz point contact of the end sphere on the rib face
    /// (computed from the curvatures), EHL traction while the spot stays inside the face overlap,
    /// boundary μ = 0.1 otherwise (seed 000 §3.1.1.7: boundary friction 0.1).
    pub end_rib: RollerEndParameters,
    /// Roller ends ↔ pocket faces: polyamide, `K_p` of a sphere R 10 mm on PA (contact at the
    /// end-face rim), μ of the cage.
    pub end_pocket: RollerEndParameters,
    /// Surface roughness R_a of rollers and raceways, m (0.16 µm and 0.2 µm: the seed's values
    /// for the aero-engine bearing 1032930, seed 000 §3.1.2 — none are given for the tapered
    /// bearing).
    pub roughness: [f64; 2],
    /// Height of the bar edges above/below the roller axis as a fraction of the local radius
    /// (0.6: the window narrows towards both sides of the pitch cone, so the cage rides on the
    /// rollers — "guided on the rolling elements").
    pub bar_edge_height: f64,
}

impl TaperedParameters {
    /// Defaults for `b` (see the field docs).
    pub fn for_bearing(b: &DoubleRowTaperedBearing) -> Self {
        let damping = 1500.0;
        let [cone_law, cup_law] = tapered_raceway_laws(b);
        let rib_k = end_rib_stiffness(b);
        let boundary = |mu: f64| TwoLevelFriction {
            mu_static: mu,
            mu_dynamic: mu,
            v_static: 5e-3,
            v_dynamic: 1e-2,
        };
        Self {
            cone: RacewayParameters {
                law: cone_law,
                damping_n_s_m: damping,
                damping_ramp_m: 1e-6,
            },
            cup: RacewayParameters {
                law: cup_law,
                damping_n_s_m: damping,
                damping_ramp_m: 1e-6,
            },
            roller_cage: PairParameters {
                k_p: bar_edge_stiffness(b),
                exponent: 1.11,
                c_h: 300.0,
                d: 1e-6,
                friction: boundary(b.cage.roller_friction),
            },
            end_rib: RollerEndParameters {
                enabled: true,
                contact: PairParameters {
                    k_p: rib_k,
                    exponent: 1.5,
                    c_h: 300.0,
                    d: 1e-6,
                    friction: boundary(0.1),
                },
                friction: EndFriction::Ehl,
            },
            end_pocket: RollerEndParameters {
                enabled: true,
                contact: PairParameters {
                    k_p: 4.0 / 3.0 * 0.5 * pa_steel_modulus(b) * 10e-3_f64.sqrt(),
                    exponent: 1.5,
                    c_h: 50.0,
                    d: 1e-6,
                    friction: boundary(b.cage.roller_friction),
                },
                friction: EndFriction::Boundary,
            },
            roughness: [0.16e-6, 0.2e-6],
            bar_edge_height: 0.6,
        }
    }
}

/// Length of the roller–bar edge contact the bar law is taken over, m.
const BAR_EDGE_LENGTH: f64 = 10e-3;

/// `K` of `Q = K δ^(10/9)` for a roller on a bar edge: Palmgren's line law rescaled to the
/// steel–cage reduced modulus over [`BAR_EDGE_LENGTH`] (the force at a 1 m approach).
fn bar_edge_stiffness(b: &DoubleRowTaperedBearing) -> f64 {
    let edge = LineContact {
        reduced_radius: 0.5 * b.roller.mean_diameter,
        reduced_modulus: pa_steel_modulus(b),
        length: BAR_EDGE_LENGTH,
    };
    edge.force_from_approach(1.0, LineApproachModel::PalmgrenScaled)
}

/// Reduced modulus E' of steel on the cage material, Pa.
fn pa_steel_modulus(b: &DoubleRowTaperedBearing) -> f64 {
    2.0 / (b.roller.material.compliance() + b.cage.material.compliance())
}

/// Principal curvatures of the large-end sphere (`1/R_s` both ways) and the rib face at the
/// seated contact: the axial-section curvature of the face (0, −1/R concave, +1/R convex) and its
/// circumferential curvature ([`rolldyn_geometry::tapered::LargeRibContact::circumferential_curvature`]:
/// −1.38 m⁻¹ for the example, so the contact conforms around the circumference, 0.19 m⁻¹
/// against 1.56 m⁻¹ in the axial section).
fn end_rib_curvatures(b: &DoubleRowTaperedBearing) -> ContactCurvatures {
    let r_s = b.roller.large_end_sphere_radius;
    ContactCurvatures {
        body1: (1.0 / r_s, 1.0 / r_s),
        body2: (
            -b.large_rib.face.curvature(),
            b.row(0).large_rib.circumferential_curvature(),
        ),
        angle: 0.0,
    }
}

/// Reduced modulus of roller and cone, Pa.
fn end_rib_modulus(b: &DoubleRowTaperedBearing) -> f64 {
    2.0 / (b.roller.material.compliance() + b.inner_material.compliance())
}

/// Hertz `K` of `Q = K δ^{3/2}` for the large-end sphere on the rib ([`end_rib_curvatures`]).
fn end_rib_stiffness(b: &DoubleRowTaperedBearing) -> f64 {
    EllipticalStiffness::new(
        &end_rib_curvatures(b),
        end_rib_modulus(b),
        EllipticalMethod::Exact,
    )
    .map(|s| s.k)
    .unwrap_or(f64::NAN)
}

/// Reduced radius of the end–rib pair in the axial section, `1/(1/R_end − κ_rib)` (seed 000
/// §3.2.2), m: the radius of the point-contact film.
fn end_rib_reduced_radius(b: &DoubleRowTaperedBearing) -> f64 {
    1.0 / (1.0 / b.roller.large_end_sphere_radius - b.large_rib.face.curvature())
}

/// Radius `R` of the film criterion's spot `√(R δ)` (SPEC §6.7: film friction while the patch
/// stays inside the mutual projection of end face and rib band). The Hertz ellipse of
/// [`end_rib_curvatures`] has its semi-minor axis `b` in the axial section, where the nearest
/// edges are (margin `m_b`: chamfer edge, undercut or rib top), and its semi-major axis `a`
/// around the circumference, bounded by the half-chord `m_a = √(R_face² − d_c²)` of the end
/// face's disk through the contact (`d_c` its distance from the roller axis). Scaled to the
/// margin the dynamics measures, the spot reaches an edge when `δ = m_b²/R` with
/// `R = max(b², a² (m_b/m_a)²)/δ` at the seated contact; `a²/δ` and `b²/δ` do not depend on the
/// load (`a, b ∝ Q^{1/3}`, `δ ∝ Q^{2/3}`), so they are taken at 1 kN, m.
fn end_rib_film_limit_radius(b: &DoubleRowTaperedBearing) -> f64 {
    let Ok(spot) = elliptical_contact(
        &end_rib_curvatures(b),
        end_rib_modulus(b),
        1e3,
        EllipticalMethod::Exact,
    ) else {
        return f64::NAN;
    };
    let row = b.row(0);
    let rib = row.large_rib;
    let (w, axis) = (rib.point - rib.end_sphere_centre, row.roller_axis);
    let d_c = (w.r * axis.z - w.z * axis.r).abs();
    let face = b.roller.large_end_face_radius();
    let m_b = (face - d_c).min(-rib.band.0).min(rib.band.1);
    let m_a = (face * face - d_c * d_c).max(0.0).sqrt();
    let minor = spot.semi_minor.powi(2);
    let major = (spot.semi_major * m_b / m_a).powi(2);
    minor.max(major) / spot.approach
}

/// Normal force at which the dynamics switches the seated roller's large-end contact from film
/// to boundary friction when the contact point lies `margin` from the nearest edge of the face
/// overlap: the Hertz law `Q = K δ^{3/2}` of [`TaperedParameters::end_rib`] at the approach of
/// [`film_limit_approach`] (SPEC §6.7), N.
pub fn end_rib_film_limit_force(b: &DoubleRowTaperedBearing, margin: f64) -> f64 {
    let stiffness = EllipticalStiffness {
        k: end_rib_stiffness(b),
    };
    stiffness
        .force(film_limit_approach(end_rib_film_limit_radius(b), margin))
        .0
}

/// The slices of one roller and their per-raceway constants.
#[derive(Debug, Clone)]
pub(crate) struct TaperedSlices {
    /// axial position of the slice centre from the roller's centre of mass, along `u`, m
    pub x: Vec<f64>,
    /// per raceway (cone, cup): perpendicular distance of the generatrix from the axis,
    /// `r cos β`, minus the profile drop and the worn depths of roller and raceway at the
    /// slice (seed 000 §3.2.3: the worn profiles interpolated linearly between the wear lines)
    pub reach: [Vec<f64>; 2],
    pub length: Vec<f64>,
    /// radius `r` at the slice centre, m
    pub radius: Vec<f64>,
    /// elastic coefficients and exponent of the cone and cup slice laws
    pub k: [Vec<f64>; 2],
    pub n: [f64; 2],
    pub damping: [Vec<SliceDamping>; 2],
}

/// Everything the right-hand side needs.
#[derive(Debug, Clone)]
pub struct TaperedModel {
    /// rollers per row
    pub z: usize,
    pub(crate) rows: [RowGeometry; 2],
    pub(crate) slices: TaperedSlices,
    pub(crate) large_end: EndGeometry,
    pub(crate) small_end: EndGeometry,
    /// roller: mass, axial and transverse inertia about the centre of mass; the centre of
    /// mass's offset from mid-length towards the large end
    pub(crate) m_r: f64,
    pub(crate) ia_r: f64,
    pub(crate) it_r: f64,
    pub(crate) x_cm: f64,
    pub(crate) half_angle: f64,
    pub(crate) m_c: f64,
    pub(crate) ia_c: f64,
    pub(crate) it_c: f64,
    /// mass of the inner-ring assembly (two cones and the spacer), kg
    pub(crate) m_i: f64,
    pub(crate) axis_i: [f64; 3],
    pub parameters: TaperedParameters,
    pub conditions: OperatingConditions,
    pub(crate) traction: TractionModel,
    /// E' of the raceway contacts, Pa; roughness R_a of roller and rings, m
    pub(crate) reduced_modulus: f64,
    pub(crate) roughness: [f64; 2],
    pub(crate) cone_angle: f64,
    pub(crate) cup_angle: f64,
    /// EHL data of the end–rib pair: reduced radius, m
    pub(crate) rib_reduced_radius: f64,
    /// radius of the film criterion's spot, [`end_rib_film_limit_radius`], m
    pub(crate) rib_film_limit_radius: f64,
    /// epicyclic cage speed at t = 0, rad/s
    pub epicyclic_cage_speed: f64,
    pub(crate) bearing: DoubleRowTaperedBearing,
}

/// Density of the cone pair and spacer: bearing steel.
fn inner_assembly_mass(b: &DoubleRowTaperedBearing, rows: &[RowGeometry; 2]) -> f64 {
    let r_in = 0.5 * b.bore;
    let r_out = rows[0].cone.rho;
    let width = b.row_spacing + b.roller.length;
    MassProperties::hollow_cylinder(r_in, r_out, width, b.inner_material.density).mass
}

impl TaperedModel {
    /// The bearing the model was built from.
    pub fn bearing(&self) -> &DoubleRowTaperedBearing {
        &self.bearing
    }

    /// Reduced modulus E' of the roller–ring contacts, Pa.
    pub fn reduced_modulus(&self) -> f64 {
        self.reduced_modulus
    }

    /// Reduced radius of the large end on the large rib (axial section, seed 000 §3.2.2), m.
    pub fn rib_reduced_radius(&self) -> f64 {
        self.rib_reduced_radius
    }

    /// The traction model of the raceway and rib contacts.
    pub fn traction_model(&self) -> &TractionModel {
        &self.traction
    }

    /// The model of `bearing` under `conditions` with `parameters` and the raceway traction
    /// `traction`.
    pub fn new(
        bearing: &DoubleRowTaperedBearing,
        conditions: OperatingConditions,
        parameters: TaperedParameters,
        traction: TractionModel,
    ) -> Result<Self, DynError> {
        bearing
            .validate()
            .map_err(|e| DynError::InvalidInput(format!("tapered bearing: {e}")))?;
        let rows = [row_geometry(bearing, 0), row_geometry(bearing, 1)];
        let roller = &bearing.roller;
        let mp = roller.mass_properties();
        let x_cm = roller.centre_of_mass_offset();
        let beta = roller.half_angle;
        let stack = roller.slices();
        let total: f64 = stack.length.iter().sum();
        let mut slices = TaperedSlices {
            x: stack.position.iter().map(|x| x - x_cm).collect(),
            reach: [0, 1].map(|race| {
                roller
                    .generatrix_reach(&stack)
                    .iter()
                    .zip(&stack.position)
                    .map(|(reach, &x)| {
                        reach - bearing.wear.roller_at(x) - bearing.wear.raceway_at(race, x)
                    })
                    .collect()
            }),
            length: stack.length.clone(),
            radius: stack.radius.clone(),
            k: [Vec::new(), Vec::new()],
            n: [0.0; 2],
            damping: [Vec::new(), Vec::new()],
        };
        for (i, p) in [parameters.cone, parameters.cup].iter().enumerate() {
            for &l in &stack.length {
                let pf = p
                    .law
                    .power_form(l)
                    .map_err(|e| DynError::InvalidInput(format!("slice law: {e}")))?;
                slices.k[i].push(pf.coefficient);
                slices.n[i] = pf.exponent;
                slices.damping[i].push(SliceDamping::new(
                    p.damping_n_s_m * l / total,
                    p.damping_ramp_m,
                ));
            }
        }
        let half = 0.5 * roller.length;
        let chamfer = roller.end_chamfer;
        let large_end = EndGeometry {
            // the worn end face recedes along the axis (seed 000 §3.2.2)
            half_length: half - x_cm - bearing.wear.large_end,
            radius: 0.5 * roller.large_diameter() - chamfer,
            sphere_curvature: 1.0 / roller.large_end_sphere_radius,
        };
        let small_end = EndGeometry {
            half_length: half + x_cm,
            radius: 0.5 * roller.small_diameter() - chamfer,
            sphere_curvature: 0.0,
        };
        let (tilt, az) = (
            conditions.misalignment_rad,
            conditions.misalignment_azimuth_rad,
        );
        let axis_i = [tilt.sin() * az.cos(), tilt.sin() * az.sin(), tilt.cos()];
        let epicyclic = bearing.epicyclic_cage_speed(conditions.inner_speed.speed(0.0));
        let reduced_modulus =
            2.0 / (roller.material.compliance() + bearing.inner_material.compliance());
        let rib_reduced_radius = end_rib_reduced_radius(bearing);
        let rib_film_limit_radius = end_rib_film_limit_radius(bearing);
        Ok(Self {
            z: bearing.rollers_per_row,
            m_i: inner_assembly_mass(bearing, &rows),
            rows,
            slices,
            large_end,
            small_end,
            m_r: mp.mass,
            ia_r: mp.axial_inertia,
            it_r: mp.transverse_inertia,
            x_cm,
            half_angle: beta,
            m_c: bearing.cage.mass,
            ia_c: bearing.cage.inertia_axial,
            it_c: bearing.cage.inertia_transverse,
            axis_i,
            parameters,
            conditions,
            traction,
            reduced_modulus,
            roughness: parameters.roughness,
            cone_angle: bearing.cone_angle(),
            cup_angle: bearing.cup_angle(),
            rib_reduced_radius,
            rib_film_limit_radius,
            epicyclic_cage_speed: epicyclic,
            bearing: bearing.clone(),
        })
    }
}
