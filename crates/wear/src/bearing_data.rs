//! What the wear calculation needs of a bearing and its oil, in SI, computed once per period
//! from the (worn) geometry.

use crate::WearError;
use crate::settings::{PressureModel, WearSettings};
use rolldyn_contact::hertz::{Conformity, reduced_modulus, reduced_radius};
use rolldyn_contact::roller_raceway::RollerRacewayContact;
use rolldyn_geometry::{BearingModel, CylindricalRollerBearing, Material};
use rolldyn_lubrication::Lubricant;
use rolldyn_lubrication::film::{hamrock_dowson_point, rigid_piezoviscous_line};
use rolldyn_lubrication::regime::film_parameter;

/// A roller ↔ raceway pair.
#[derive(Debug, Clone, PartialEq)]
pub struct RacewayPair {
    pub raceway_radius_m: f64,
    pub reduced_radius_m: f64,
    pub reduced_modulus_pa: f64,
    pub ring_hardness_pa: f64,
}

/// The roller ↔ cage-bar pair: the roller on the flat bar face.
#[derive(Debug, Clone, PartialEq)]
pub struct BarPair {
    pub reduced_radius_m: f64,
    pub reduced_modulus_pa: f64,
    pub hardness_pa: f64,
    /// ρ of seed 000 eq. (3.1) for the bar: the cage floating clearance, over which the
    /// contact line wanders across the bar face as the cage floats, m
    pub exposure_length_m: f64,
    /// Ra of the roller and of the bar, m
    pub roughness_m: [f64; 2],
}

/// The roller-end ↔ rib pair.
#[derive(Debug, Clone, PartialEq)]
pub struct EndPair {
    /// the radius a flat end meets a flat rib with: the roller's edge break, m
    pub edge_radius_m: f64,
    pub reduced_modulus_pa: f64,
    pub ring_hardness_pa: f64,
    /// Ra of the roller end (the roller's) and of the rib (its ring's), m
    pub roughness_m: [f64; 2],
}

/// The bearing as the wear calculation sees it.
#[derive(Debug, Clone)]
pub struct WearData {
    pub roller_count: usize,
    pub roller_diameter_m: f64,
    pub roller_hardness_pa: f64,
    pub slice_positions_m: Vec<f64>,
    pub slice_lengths_m: Vec<f64>,
    pub slice_drops_m: Vec<f64>,
    pub inner: RacewayPair,
    pub outer: RacewayPair,
    pub bar: BarPair,
    pub ends: EndPair,
    /// oil viscosity and pressure–viscosity coefficient at the cage temperature
    pub oil_viscosity_pa_s: f64,
    pub oil_pressure_viscosity_1_pa: f64,
    /// the roller on the inner and the outer raceway for the Boussinesq wear-line pressures
    /// (`PressureModel::Boussinesq`): the inner contact tilted by the ring misalignment
    contacts: Option<[RollerRacewayContact; 2]>,
}

fn hardness(material: &Material, key: &str, settings: &WearSettings) -> Result<f64, WearError> {
    let h = material.meyer_hardness.ok_or_else(|| WearError::Key {
        key: format!("materials.{}.meyer_hardness", material.name),
        reason: format!("missing: the wear of the {key} needs the Meyer hardness"),
    })?;
    Ok(if settings.seed_literal_hardness {
        crate::law::seed_literal_hardness_pa(h)
    } else {
        h
    })
}

/// Whether the roller ends run on the inner ring's ribs (else the outer ring's).
pub fn ribs_on_inner_ring(bearing: &CylindricalRollerBearing) -> bool {
    !bearing.inner_ring.ribs.is_empty() || bearing.outer_ring.ribs.is_empty()
}

/// The roller on both raceways of the (worn) bearing: the inner contact tilted by the ring
/// misalignment (the rollers follow the outer ring), the outer one straight.
fn raceway_contacts(
    bearing: &CylindricalRollerBearing,
) -> Result<[RollerRacewayContact; 2], WearError> {
    let model = BearingModel::Cylindrical(bearing.clone());
    let contact = |inner: bool, tilt: f64| {
        RollerRacewayContact::from_model(&model, inner, tilt)
            .map_err(|e| WearError::Input(format!("Boussinesq wear-line pressures: {e}")))
    };
    Ok([
        contact(true, bearing.misalignment.inner_ring_tilt)?,
        contact(false, 0.0)?,
    ])
}

fn modulus(a: &Material, b: &Material) -> f64 {
    reduced_modulus(
        a.youngs_modulus,
        a.poisson_ratio,
        b.youngs_modulus,
        b.poisson_ratio,
    )
}

impl WearData {
    /// The wear data of `bearing` with `oil` at the cage temperature `cage_k`.
    pub fn new(
        bearing: &CylindricalRollerBearing,
        oil: &Lubricant,
        cage_k: f64,
        settings: &WearSettings,
    ) -> Result<Self, WearError> {
        let roller = &bearing.roller;
        let rw = 0.5 * roller.diameter;
        let stack = roller.slices();
        let cage = bearing.cage.as_ref().ok_or_else(|| {
            WearError::Input("[cage] is needed for the wear of the cage bars".into())
        })?;
        let pair =
            |ring: &rolldyn_geometry::Ring, conformity, key| -> Result<RacewayPair, WearError> {
                let r = 0.5 * ring.raceway_diameter;
                Ok(RacewayPair {
                    raceway_radius_m: r,
                    reduced_radius_m: reduced_radius(rw, r, conformity)
                        .map_err(|e| WearError::Input(format!("{key}: {e}")))?,
                    reduced_modulus_pa: modulus(&roller.material, &ring.material),
                    ring_hardness_pa: hardness(&ring.material, key, settings)?,
                })
            };
        let ribbed = if ribs_on_inner_ring(bearing) {
            &bearing.inner_ring
        } else {
            &bearing.outer_ring
        };
        let oil_error =
            |e: rolldyn_lubrication::LubError| WearError::Input(format!("[lubricant]: {e}"));
        Ok(Self {
            roller_count: bearing.roller_count,
            roller_diameter_m: roller.diameter,
            roller_hardness_pa: hardness(&roller.material, "rollers", settings)?,
            slice_positions_m: stack.position,
            slice_lengths_m: stack.length,
            slice_drops_m: stack.drop,
            inner: pair(
                &bearing.inner_ring,
                Conformity::ConvexConvex,
                "inner raceway",
            )?,
            outer: pair(
                &bearing.outer_ring,
                Conformity::ConvexConcave,
                "outer raceway",
            )?,
            bar: BarPair {
                reduced_radius_m: rw,
                reduced_modulus_pa: modulus(&roller.material, &cage.material),
                hardness_pa: hardness(&cage.material, "cage bars", settings)?,
                exposure_length_m: cage.floating_clearance,
                roughness_m: [roller.roughness_ra, cage.roughness_ra],
            },
            ends: EndPair {
                edge_radius_m: roller.edge_break,
                reduced_modulus_pa: modulus(&roller.material, &ribbed.material),
                ring_hardness_pa: hardness(&ribbed.material, "ribs", settings)?,
                roughness_m: [roller.roughness_ra, ribbed.roughness_ra],
            },
            oil_viscosity_pa_s: oil.dynamic_viscosity(cage_k).map_err(oil_error)?,
            oil_pressure_viscosity_1_pa: oil.pressure_viscosity(cage_k).map_err(oil_error)?,
            contacts: match settings.pressure_model {
                PressureModel::Slices => None,
                PressureModel::Boussinesq => Some(raceway_contacts(bearing)?),
            },
        })
    }

    /// The roller on the inner (`inner`) or outer raceway for Boussinesq pressures, if built.
    pub fn boussinesq(&self, inner: bool) -> Option<&RollerRacewayContact> {
        self.contacts.as_ref().map(|c| &c[usize::from(!inner)])
    }

    /// Number of wear lines on the roller (its slice centres).
    pub fn lines(&self) -> usize {
        self.slice_positions_m.len()
    }

    /// Λ at the roller ↔ bar contact: the rigid–piezoviscous line film (seed 000 eq. 2.17, as
    /// the seed's §3.1.1.5) of the roller sliding on the still bar (entrainment v/2) over the
    /// straight length, on Λ of seed 000 eq. (1.2).
    pub fn bar_lambda(&self, force_n: f64, sliding_m_s: f64) -> f64 {
        let z_min = self
            .slice_drops_m
            .iter()
            .copied()
            .fold(f64::INFINITY, f64::min);
        let straight: f64 = self
            .slice_lengths_m
            .iter()
            .zip(&self.slice_drops_m)
            .filter(|&(_, &z)| z <= z_min)
            .map(|(l, _)| l)
            .sum();
        let h = rigid_piezoviscous_line(
            self.oil_viscosity_pa_s,
            self.oil_pressure_viscosity_1_pa,
            0.5 * sliding_m_s,
            force_n,
            straight,
            self.bar.reduced_modulus_pa,
            self.bar.reduced_radius_m,
        );
        film_parameter(h, self.bar.roughness_m[0], self.bar.roughness_m[1])
    }

    /// Λ at a roller-end ↔ rib contact in film friction: the Hamrock–Dowson circular-point
    /// minimum film at entrainment `entrainment_m_s`.
    pub fn rib_lambda(&self, force_n: f64, entrainment_m_s: f64, reduced_radius_m: f64) -> f64 {
        let (_, h_min) = hamrock_dowson_point(
            self.oil_viscosity_pa_s,
            self.oil_pressure_viscosity_1_pa,
            entrainment_m_s,
            force_n,
            self.ends.reduced_modulus_pa,
            reduced_radius_m,
            1.0,
        );
        film_parameter(h_min, self.ends.roughness_m[0], self.ends.roughness_m[1])
    }
}
