//! The immutable, precomputed description of one bearing run: geometry reduced to the numbers
//! the right-hand side needs (slices as struct-of-arrays), contact laws, traction models,
//! operating conditions.

use crate::conditions::OperatingConditions;
use crate::error::DynError;
use crate::land::{CageLandModel, TwoLevelLand};
use crate::layout::Layout;
use crate::parameters::ContactParameters;
use rolldyn_contact::damping::SliceDamping;
use rolldyn_geometry::{CageGuidance, CylindricalRollerBearing, Profile};
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
    /// elastic coefficient k_s of `Q_s = k_s δⁿ` per slice, N/mⁿ
    pub k: Vec<f64>,
    /// exponent n
    pub n: f64,
    /// damping ramp per slice (C_max share, δ*)
    pub damping: Vec<SliceDamping>,
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
}

/// Cage guiding-land geometry.
#[derive(Debug, Clone, Copy)]
pub(crate) struct LandGeometry {
    pub inner: bool,
    pub radius: f64,
    pub gap: f64,
    pub width: f64,
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
    pub slice_len: Vec<f64>,
    pub slice_drop: Vec<f64>,
    pub inner: RacewaySlices,
    pub outer: RacewaySlices,
    /// inner raceway radius R_i, m
    pub ri: f64,
    /// effective outer raceway radius R_i + D_w + G_r/2, m
    pub ro: f64,
    pub traction: RacewayTraction,
    // cage
    pub m_c: f64,
    pub ia_c: f64,
    pub it_c: f64,
    pub r_bar: f64,
    pub half_pocket: f64,
    pub bar_x: [f64; 2],
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
    /// γ = D_w/d_m
    pub gamma: f64,
    /// penetration reported as divergence, m
    pub div_limit: f64,
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
        let ri = 0.5 * bearing.inner_ring.raceway_diameter;
        let ro = ri + roller.diameter + 0.5 * bearing.clearance.radial;
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
        let total_len: f64 = stack.length.iter().sum();
        let mk = |law: rolldyn_contact::slices::SliceLaw,
                  damping_total: f64,
                  ramp: f64,
                  reduced_radius: f64,
                  ring: &rolldyn_geometry::Ring,
                  temperature_k: f64|
         -> Result<RacewaySlices, DynError> {
            let mut k = Vec::with_capacity(stack.length.len());
            let mut damping = Vec::with_capacity(stack.length.len());
            for &l in &stack.length {
                let pf = law
                    .power_form(l)
                    .map_err(|e| DynError::InvalidInput(format!("slice law: {e}")))?;
                k.push(pf.coefficient);
                damping.push(SliceDamping::new(damping_total * l / total_len, ramp));
            }
            let e1 = &roller.material;
            let e2 = &ring.material;
            let reduced_modulus = 2.0 / (e1.compliance() + e2.compliance());
            Ok(RacewaySlices {
                k,
                n: law.exponent(),
                damping,
                reduced_radius,
                reduced_modulus,
                roughness: [roller.roughness_ra, ring.roughness_ra],
                temperature_k,
                profile: ring.raceway_profile.clone(),
            })
        };
        let t = &conditions.temperatures;
        let inner = mk(
            params.inner_raceway.law,
            params.inner_raceway.damping_n_s_m,
            params.inner_raceway.damping_ramp_m,
            rw * ri / (rw + ri),
            &bearing.inner_ring,
            t.inner_raceway_k,
        )?;
        let outer = mk(
            params.outer_raceway.law,
            params.outer_raceway.damping_n_s_m,
            params.outer_raceway.damping_ramp_m,
            rw * ro / (ro - rw),
            &bearing.outer_ring,
            t.outer_raceway_k,
        )?;
        let land = match cage.guidance {
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
        };
        let rm = 0.5 * bearing.pitch_diameter();
        let h = roller.profile.chamfer_start().min(0.5 * roller.length);
        let (s, c) = conditions.misalignment_azimuth_rad.sin_cos();
        let (sb, cb) = conditions.misalignment_rad.sin_cos();
        let axis_i = [sb * c, sb * s, cb];
        Ok(Self {
            layout: Layout { rollers: z },
            z,
            m_r: mp.mass,
            ia_r: mp.axial_inertia,
            it_r: mp.transverse_inertia,
            rw,
            slice_x: stack.position.clone(),
            slice_len: stack.length.clone(),
            slice_drop: stack.drop.clone(),
            inner,
            outer,
            ri,
            ro,
            traction,
            m_c: cmp.mass,
            ia_c: cmp.axial_inertia,
            it_c: cmp.transverse_inertia,
            r_bar: 0.5 * cage.bar_contact_diameter,
            half_pocket: 0.5 * cage.pocket_circumferential,
            bar_x: [-h, h],
            land,
            land_model: Box::new(TwoLevelLand {
                parameters: params.cage_land,
            }),
            m_i,
            axis_i,
            conditions,
            params,
            rm,
            gamma: roller.diameter / bearing.pitch_diameter(),
            div_limit: 1e-4,
        })
    }

    /// Epicyclic cage speed for ring speeds (ω_i, ω_o).
    #[inline]
    pub fn epicyclic(&self, wi: f64, wo: f64) -> f64 {
        0.5 * (wi * (1.0 - self.gamma) + wo * (1.0 + self.gamma))
    }
}
