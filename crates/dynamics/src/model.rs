//! The immutable, precomputed description of one bearing run: geometry reduced to the numbers
//! the right-hand side needs (slices as struct-of-arrays), contact laws, traction models,
//! operating conditions.

use crate::conditions::OperatingConditions;
use crate::ends::{EndGeometry, FaceGeometry};
use crate::error::DynError;
use crate::land::{CageLandModel, TwoLevelLand};
use crate::layout::Layout;
use crate::parameters::{ContactParameters, RacewayParameters};
use crate::settings::DynamicsSettings;
use crate::slice_kernel::SliceConstants;
use rolldyn_contact::bar_force::BarForceLaw;
use rolldyn_contact::damping::SliceDamping;
use rolldyn_geometry::{
    Cage, CageGuidance, CylindricalRollerBearing, EndFace, PocketWalls, Profile, RacewayWearMap,
    RibFace, RibSide, Ring,
};
use rolldyn_lubrication::TractionModel;

/// Traction models of the two raceways (the same model twice is the usual case).
#[derive(Debug, Clone, PartialEq)]
pub struct RacewayTraction {
    /// roller slices ↔ inner raceway
    pub inner: TractionModel,
    /// roller slices ↔ outer raceway
    pub outer: TractionModel,
}

impl RacewayTraction {
    /// The same model on both raceways.
    pub fn same(model: TractionModel) -> Self {
        Self {
            inner: model.clone(),
            outer: model,
        }
    }
}

/// Roller slices against one raceway (struct of arrays).
#[derive(Debug, Clone)]
pub(crate) struct RacewaySlices {
    /// the per-slice constants below, repeated for every roller (slot layout of the vectorised
    /// slice kernel)
    pub lanes: SliceConstants,
    /// elastic coefficient k_s of `Q_s = k_s δⁿ` per slice, N/mⁿ
    pub k: Vec<f64>,
    /// exponent n
    pub n: f64,
    /// reduced radius R' in the rolling direction, m (seed 000 (1.12))
    pub reduced_radius: f64,
    /// reduced modulus E' (seed 000 (1.13)), Pa
    pub reduced_modulus: f64,
    /// roughness R_a of roller and ring, m
    pub roughness: [f64; 2],
    /// oil temperature, K
    pub temperature_k: f64,
    /// raceway generatrix (None = straight)
    pub profile: Option<Profile>,
    /// raceway wear over axial position × ring angle (None = unworn), read at each roller's
    /// angle on the ring
    pub wear: Option<RacewayWearMap>,
    /// smallest raceway drop over the roller length (≤ 0), m — bounds the approach in the
    /// contact pre-check (wear only deepens the raceway: the profile alone gives the bound)
    pub min_drop: f64,
}

/// Cage guiding-land geometry.
#[derive(Debug, Clone, Copy)]
pub(crate) struct LandGeometry {
    pub inner: bool,
    pub radius: f64,
    pub gap: f64,
    pub width: f64,
}

/// Roller-end contacts: end geometry, rib faces of both rings, cage pocket faces.
#[derive(Debug, Clone)]
pub(crate) struct EndContacts {
    pub end: EndGeometry,
    /// inner-ring rib faces (ring frame)
    pub inner_ribs: Vec<FaceGeometry>,
    /// outer-ring rib faces
    pub outer_ribs: Vec<FaceGeometry>,
    /// the two pocket faces of every pocket (cage frame)
    pub pocket: [FaceGeometry; 2],
    pub rib_damping: SliceDamping,
    pub pocket_damping: SliceDamping,
    /// EHL data of the end–rib pair: reduced radius (∞: flat–flat, no film model), m
    pub rib_reduced_radius: f64,
    pub rib_reduced_modulus: f64,
    pub rib_roughness: [f64; 2],
}

impl RacewaySlices {
    /// The slices of every roller on the raceway of `ring` with the slice law and damping of
    /// `raceway` (the damping shared by the slices in proportion to their length), the reduced
    /// radius and modulus of the pair, and its temperature.
    fn new(
        bearing: &CylindricalRollerBearing,
        raceway: &RacewayParameters,
        reduced_radius: f64,
        ring: &Ring,
        temperature_k: f64,
    ) -> Result<Self, DynError> {
        let roller = &bearing.roller;
        let stack = roller.slices();
        let total_len: f64 = stack.length.iter().sum();
        let mut k = Vec::with_capacity(stack.length.len());
        let mut damping = Vec::with_capacity(stack.length.len());
        for &l in &stack.length {
            let pf = raceway
                .law
                .power_form(l)
                .map_err(|e| DynError::InvalidInput(format!("slice law: {e}")))?;
            k.push(pf.coefficient);
            damping.push(SliceDamping::new(
                raceway.damping_n_s_m * l / total_len,
                raceway.damping_ramp_m,
            ));
        }
        let e1 = &roller.material;
        let e2 = &ring.material;
        let reduced_modulus = 2.0 / (e1.compliance() + e2.compliance());
        let min_drop = ring.raceway_profile.as_ref().map_or(0.0, |pr| {
            // the profile clamps beyond its ends: sampling its length finds its minimum
            (0..=400)
                .map(|i| pr.drop(roller.length * (i as f64 / 400.0 - 0.5) * 2.0))
                .fold(0.0, f64::min)
        });
        let lanes = SliceConstants::new(
            bearing.roller_count,
            &stack.position,
            &stack.drop,
            &stack.length,
            &k,
            &damping,
        );
        Ok(RacewaySlices {
            lanes,
            k,
            n: raceway.law.exponent(),
            reduced_radius,
            reduced_modulus,
            roughness: [roller.roughness_ra, ring.roughness_ra],
            temperature_k,
            profile: ring.raceway_profile.clone(),
            wear: ring.raceway_wear.clone(),
            min_drop,
        })
    }
}

impl LandGeometry {
    /// The guiding land of a land-guided cage (`None` for a roller-guided one): the land of the
    /// guiding ring, no wider than the cage, and half the floating clearance as radial gap.
    fn of(bearing: &CylindricalRollerBearing, cage: &Cage) -> Option<Self> {
        match cage.guidance {
            CageGuidance::Rollers => None,
            g => {
                let inner_land = g == CageGuidance::InnerLand;
                let ring = if inner_land {
                    &bearing.inner_ring
                } else {
                    &bearing.outer_ring
                };
                let land_d = cage.land_diameter().unwrap_or(0.0);
                let width = ring
                    .guiding_land
                    .map(|l| l.width)
                    .unwrap_or(cage.width)
                    .min(cage.width);
                Some(LandGeometry {
                    inner: inner_land,
                    radius: 0.5 * land_d,
                    gap: 0.5 * cage.floating_clearance,
                    width,
                })
            }
        }
    }
}

impl EndContacts {
    /// Roller ends ↔ ribs and pocket faces (SPEC §1.2, §1.3, §3.3 pairs 56 and 54): the flat
    /// end of the roller, the rib faces of both rings, the two pocket faces, and the EHL data of
    /// the end–rib pair (reduced radius from the end-sphere and rib-torus curvatures, the modulus
    /// and roughness of the inner raceway pair `inner`).
    fn new(
        bearing: &CylindricalRollerBearing,
        cage: &Cage,
        params: &ContactParameters,
        ri: f64,
        ro: f64,
        inner: &RacewaySlices,
    ) -> Result<Self, DynError> {
        let roller = &bearing.roller;
        let rw = 0.5 * roller.diameter;
        let spacing_of = |ring: &Ring| {
            ring.rib_spacing
                .unwrap_or(roller.length + bearing.roller_rib_axial_clearance().unwrap_or(0.0))
        };
        let end_radius = rw - roller.profile.drop(0.5 * roller.length) - roller.edge_break;
        if end_radius <= 0.0 {
            return Err(DynError::InvalidInput(
                "roller end face: chamfer and edge break leave no flat end".into(),
            ));
        }
        let sphere_curvature = match roller.end_face {
            EndFace::Flat => 0.0,
            EndFace::Sphere { radius } => 1.0 / radius,
        };
        let rib_curvature = bearing
            .inner_ring
            .ribs
            .iter()
            .chain(&bearing.outer_ring.ribs)
            .map(|r| match r.face {
                RibFace::ConvexTorus { radius, .. } => 1.0 / radius,
                RibFace::ConcaveTorus { radius } => -1.0 / radius,
                _ => 0.0,
            })
            .fold(0.0_f64, f64::max);
        let sum_curvature = sphere_curvature + rib_curvature;
        let pocket_band = (0.5 * cage.inner_diameter, 0.5 * cage.outer_diameter);
        let pocket_face = |side: f64| FaceGeometry {
            side,
            zeta: 0.5 * side * cage.pocket.axial,
            rho_lo: pocket_band.0,
            rho_hi: pocket_band.1,
            rho_edge: pocket_band.1,
            rho_c: 0.5 * (pocket_band.0 + pocket_band.1),
            slope: 0.0,
            curvature: 0.0,
        };
        let pe = &params.roller_end_rib.contact;
        let pc = &params.roller_end_cage.contact;
        Ok(Self {
            end: EndGeometry {
                half_length: 0.5 * roller.length,
                radius: end_radius,
                sphere_curvature,
            },
            inner_ribs: rib_faces(
                &bearing.inner_ring,
                true,
                ri,
                spacing_of(&bearing.inner_ring),
            )?,
            outer_ribs: rib_faces(
                &bearing.outer_ring,
                false,
                ro,
                spacing_of(&bearing.outer_ring),
            )?,
            pocket: [pocket_face(-1.0), pocket_face(1.0)],
            rib_damping: SliceDamping::new(pe.c_h, pe.d),
            pocket_damping: SliceDamping::new(pc.c_h, pc.d),
            rib_reduced_radius: if sum_curvature > 0.0 {
                1.0 / sum_curvature
            } else {
                f64::INFINITY
            },
            rib_reduced_modulus: inner.reduced_modulus,
            rib_roughness: inner.roughness,
        })
    }
}

/// Rib faces of a ring (SPEC §1.2): face position from the rib spacing (or roller length plus
/// the roller–rib axial clearance), band from the raceway to the rim minus its edge break,
/// crest of a convex torus at mid-height shifted by `crest_offset` toward the raceway.
fn rib_faces(
    ring: &Ring,
    inner: bool,
    raceway_radius: f64,
    spacing: f64,
) -> Result<Vec<FaceGeometry>, DynError> {
    let mut out = Vec::with_capacity(ring.ribs.len());
    for rib in &ring.ribs {
        let side = match rib.side {
            RibSide::Left => -1.0,
            RibSide::Right => 1.0,
        };
        let rim = 0.5 * rib.diameter;
        // σ = +1 when ρ grows away from the raceway (inner ring)
        let sigma = if inner { 1.0 } else { -1.0 };
        let (rho_lo, rho_hi) = if inner {
            (raceway_radius, rim - rib.edge_break)
        } else {
            (rim + rib.edge_break, raceway_radius)
        };
        if rho_hi <= rho_lo {
            return Err(DynError::InvalidInput(format!(
                "rib rim Ø{:.3} mm leaves no face on the {} ring",
                rib.diameter * 1e3,
                if inner { "inner" } else { "outer" }
            )));
        }
        let mid = 0.5 * (raceway_radius + rim);
        let (rho_c, slope, curvature) = match rib.face {
            RibFace::Flat => (mid, 0.0, 0.0),
            // face inclined by α from the radial plane; positive α leans the face rim toward
            // the roller
            RibFace::Cone { angle } => (mid, sigma * angle.tan(), 0.0),
            RibFace::ConvexTorus {
                radius,
                crest_offset,
            } => (mid - sigma * crest_offset, 0.0, 1.0 / radius),
            RibFace::ConcaveTorus { radius } => (mid, 0.0, -1.0 / radius),
        };
        out.push(FaceGeometry {
            side,
            zeta: 0.5 * side * spacing,
            rho_lo,
            rho_hi,
            rho_edge: if inner { rho_hi } else { rho_lo },
            rho_c,
            slope,
            curvature,
        });
    }
    Ok(out)
}

/// Precomputed model.
#[derive(Debug)]
pub(crate) struct Model {
    pub layout: Layout,
    pub z: usize,
    // roller
    pub m_r: f64,
    pub ia_r: f64,
    pub it_r: f64,
    pub rw: f64,
    pub slice_x: Vec<f64>,
    pub slice_drop: Vec<f64>,
    /// largest |x| of a slice centre along the roller axis, m
    pub slice_reach: f64,
    /// smallest slice drop (≤ 0), m
    pub min_slice_drop: f64,
    pub inner: RacewaySlices,
    pub outer: RacewaySlices,
    /// (sin, cos) of the pocket angles 2πj/Z relative to the cage angle
    pub pocket_sin_cos: Vec<(f64, f64)>,
    /// inner raceway radius R_i, m
    pub ri: f64,
    /// effective outer raceway radius R_i + D_w + G_r/2, m
    pub ro: f64,
    /// operating radial clearance G_r of the bearing, m
    pub clearance: f64,
    pub traction: RacewayTraction,
    // cage
    pub m_c: f64,
    pub ia_c: f64,
    pub it_c: f64,
    /// the pocket walls of the cage profile, pocket coordinates (docs/theory.md §1.6)
    pub pocket: PocketWalls,
    /// axial length of each roller slice, m (the pair-34 law takes its share `l_i/L_b` of the
    /// law for the roller's line contact on a flat bar, [`BarForceLaw::normal_force`])
    pub slice_length: Vec<f64>,
    pub land: Option<LandGeometry>,
    pub land_model: Box<dyn CageLandModel>,
    // inner ring
    pub m_i: f64,
    /// inner-ring axis (unit, prescribed misalignment)
    pub axis_i: [f64; 3],
    pub conditions: OperatingConditions,
    pub params: ContactParameters,
    /// pitch radius d_m/2, m
    pub rm: f64,
    /// diameters (d_i, D_o) of the raceways the rollers roll on (the contact geometry, with the
    /// radial clearance), the epicyclic cage speed's reference, m
    pub raceway_diameters: (f64, f64),
    /// penetration reported as divergence, m ([`DynamicsSettings::divergence_penetration_m`])
    pub div_limit: f64,
    /// pair-34 force law per roller slice ([`ContactParameters::roller_cage_law`] over the
    /// roller's bar contact length)
    pub bar_law: BarForceLaw,
    /// roller ends ↔ ribs and cage pocket faces
    pub ends: EndContacts,
}

impl Model {
    pub fn new(
        bearing: &CylindricalRollerBearing,
        conditions: OperatingConditions,
        params: ContactParameters,
        traction: RacewayTraction,
    ) -> Result<Self, DynError> {
        bearing
            .validate()
            .map_err(|e| DynError::InvalidInput(format!("{}: {}", e.key, e.reason)))?;
        conditions.validate()?;
        params.validate()?;
        let cage = bearing.cage.as_ref().ok_or_else(|| {
            DynError::InvalidInput(
                "the dynamics needs a cage (full-complement bearings are not modelled)".into(),
            )
        })?;
        let z = bearing.roller_count;
        let roller = &bearing.roller;
        let rw = 0.5 * roller.diameter;
        let raceway_diameters = bearing.rolling_raceway_diameters();
        let (ri, ro) = (0.5 * raceway_diameters.0, 0.5 * raceway_diameters.1);
        let stack = roller.slices();
        let mp = roller.mass_properties;
        if !(mp.mass > 0.0 && mp.axial_inertia > 0.0 && mp.transverse_inertia > 0.0) {
            return Err(DynError::InvalidInput(
                "roller mass properties must be positive".into(),
            ));
        }
        let cmp = cage.mass_properties;
        if !(cmp.mass > 0.0 && cmp.axial_inertia > 0.0 && cmp.transverse_inertia > 0.0) {
            return Err(DynError::InvalidInput(
                "cage mass properties must be positive".into(),
            ));
        }
        let m_i = match conditions.support.mass_kg {
            Some(m) => m,
            None => bearing.inner_ring.mass_properties.mass,
        };
        if m_i.is_nan() || m_i <= 0.0 {
            return Err(DynError::InvalidInput(
                "inner-ring mass must be positive".into(),
            ));
        }
        let t = &conditions.temperatures;
        let inner = RacewaySlices::new(
            bearing,
            &params.inner_raceway,
            rw * ri / (rw + ri),
            &bearing.inner_ring,
            t.inner_raceway_k,
        )?;
        let outer = RacewaySlices::new(
            bearing,
            &params.outer_raceway,
            rw * ro / (ro - rw),
            &bearing.outer_ring,
            t.outer_raceway_k,
        )?;
        let land = LandGeometry::of(bearing, cage);
        let rm = 0.5 * bearing.pitch_diameter();
        let (s, c) = conditions.misalignment_azimuth_rad.sin_cos();
        let (sb, cb) = conditions.misalignment_rad.sin_cos();
        let axis_i = [sb * c, sb * s, cb];
        let ends = EndContacts::new(bearing, cage, &params, ri, ro, &inner)?;
        let defaults = DynamicsSettings::default();
        let bar_law = params.roller_cage_law(bearing.roller.bar_contact_length());
        Ok(Self {
            layout: Layout { rollers: z },
            z,
            m_r: mp.mass,
            ia_r: mp.axial_inertia,
            it_r: mp.transverse_inertia,
            rw,
            slice_x: stack.position.clone(),
            slice_drop: stack.drop.clone(),
            slice_reach: stack.position.iter().fold(0.0, |a, x| a.max(x.abs())),
            min_slice_drop: stack.drop.iter().fold(0.0, |a, &d| a.min(d)),
            inner,
            outer,
            pocket_sin_cos: (0..z)
                .map(|j| (std::f64::consts::TAU * j as f64 / z as f64).sin_cos())
                .collect(),
            ri,
            ro,
            clearance: bearing.clearance.radial,
            traction,
            m_c: cmp.mass,
            ia_c: cmp.axial_inertia,
            it_c: cmp.transverse_inertia,
            pocket: cage
                .pocket
                .walls(&bearing.pocket_context(cage))
                .map_err(|e| DynError::InvalidInput(e.to_string()))?,
            slice_length: stack.length.clone(),
            land,
            land_model: Box::new(TwoLevelLand {
                parameters: params.cage_land,
            }),
            m_i,
            axis_i,
            conditions,
            params,
            rm,
            raceway_diameters,
            bar_law,
            div_limit: defaults.divergence_penetration_m,
            ends,
        })
    }

    /// Takes the run settings that enter the right-hand side.
    pub fn apply(&mut self, settings: &DynamicsSettings) {
        self.div_limit = settings.divergence_penetration_m;
    }

    /// Epicyclic cage speed for ring speeds (ω_i, ω_o): [`rolldyn_geometry::epicyclic_cage_speed`].
    #[inline]
    pub fn epicyclic(&self, wi: f64, wo: f64) -> f64 {
        let (di, do_) = self.raceway_diameters;
        rolldyn_geometry::epicyclic_cage_speed(di, do_, wi, wo)
    }
}
