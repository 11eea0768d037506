//! Validation studies of the quasi-static model, as data for tests, tables and plots.
//!
//! * [`obrien_taylor`] — SPEC V-06 / seed 000 §2.3: the O'Brien & Taylor test bearing
//!   (seed 000 Table 2.2) with NVI 65, cage slip vs radial load at 1500/2500/4000/4500 rpm and
//!   vs misalignment at 201 N.
//! * [`intershaft_bearing`], [`ipm10_assumed`], [`intershaft_conditions`] — SPEC V-18 /
//!   seed 001: an intershaft bearing whose geometry the seed does not give (SPEC §1.6 g), chosen
//!   here and documented, with the seed's operating data (F_r = 50 N, 47.3/43 °C rings, mounting
//!   clearance 0.043 mm, n_н = 13 067 rpm, n_в = 8152 rpm).

use crate::conditions::{FrictionModel, PartTemperatures, QuasiStaticConditions, celsius, rpm};
use crate::options::QuasiStaticOptions;
use rolldyn_geometry::{
    Cage, CageGuidance, CagePocket, Chamfer, Clearance, CylindricalRollerBearing, EndFace,
    GuidingLand, MassProperties, Material, Misalignment, PocketFaces, Profile, ProfileShape, Rib,
    RibFace, RibSide, Ring, Roller,
};
use rolldyn_lubrication::lubricant::MixedLimitsData;
use rolldyn_lubrication::{
    FilmFormula, Lubricant, MixedLimits, MurakiSettings, Rheology, TempLaw, ViscosityLaw,
    lubricant_by_name,
};
use serde::Serialize;

// ---------------------------------------------------------------------------------------------
// O'Brien & Taylor (SPEC V-06)
// ---------------------------------------------------------------------------------------------

/// Inner-ring speeds of the O'Brien–Taylor tests, rpm (seed 000 Fig. 2.14).
pub const OBRIEN_TAYLOR_SPEEDS_RPM: [f64; 4] = [1500.0, 2500.0, 4000.0, 4500.0];
/// Radial loads of the study, N (seed 000: "from 104 N to 687 N").
pub const OBRIEN_TAYLOR_LOADS_N: [f64; 7] = [104.0, 201.0, 300.0, 400.0, 500.0, 600.0, 687.0];
/// Misalignments of the study at 201 N, arc minutes (the seed does not tabulate the angles of
/// Fig. 2.14b; 0…10′ spans the usual range of such tests).
pub const OBRIEN_TAYLOR_MISALIGNMENTS_ARCMIN: [f64; 6] = [0.0, 2.0, 4.0, 6.0, 8.0, 10.0];

/// Oil temperature of seed 000 Table 2.4 for an inner-ring speed, °C (1500 → 44, 2500 → 49.5,
/// 4000 → 54.5, 4500 → 59; linear in between, end values held outside).
pub fn obrien_taylor_temperature_c(speed_rpm: f64) -> f64 {
    const T: [(f64, f64); 4] = [
        (1500.0, 44.0),
        (2500.0, 49.5),
        (4000.0, 54.5),
        (4500.0, 59.0),
    ];
    if speed_rpm <= T[0].0 {
        return T[0].1;
    }
    for w in T.windows(2) {
        if speed_rpm <= w[1].0 {
            let f = (speed_rpm - w[0].0) / (w[1].0 - w[0].0);
            return w[0].1 + f * (w[1].1 - w[0].1);
        }
    }
    T[3].1
}

/// The bearing of `examples/obrien-taylor.toml` with the surface finish seed 000 §2.3 adopts
/// for the study: Ra = 0.32 µm on the raceways, 0.16 µm on the rollers (SPEC V-06).
pub fn obrien_taylor_bearing(base: &CylindricalRollerBearing) -> CylindricalRollerBearing {
    let mut b = base.clone();
    b.inner_ring.roughness_ra = 0.32e-6;
    b.outer_ring.roughness_ra = 0.32e-6;
    b.roller.roughness_ra = 0.16e-6;
    b
}

/// Hydrodynamic traction law of NVI 65 in the O'Brien–Taylor study.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum NviTraction {
    /// SPEC V-06 literally: elastic (first) term of (1.4) only, μ_hd = Γ s b/(h p̄), Γ = 3 GPa
    /// (capped at 0.1).
    Seed000Elastic,
    /// Variant (not in the seeds): Maxwell–Eyring without self-heating — the isothermal Muraki
    /// branch of the lubrication crate (SPEC §4.5, "friction curve without self-heating") with
    /// the same Γ = 3 GPa and an Eyring stress `tau0_pa` (NVI 65 has none in the seeds). At the
    /// low pressures of this bearing (p̄ ≈ 0.1…0.4 GPa, Deborah number ≪ 1) it reduces to the
    /// Newtonian shear η(p̄) v/h, whereas the elastic-only law remains very stiff there.
    MaxwellEyring {
        /// Eyring stress τ0, Pa.
        tau0_pa: f64,
    },
}

/// Operating conditions of one O'Brien–Taylor point (SPEC V-06): inner ring at `speed_rpm`,
/// outer ring at rest, NVI 65 with the seed 000 mixed model (Λ_bd = 1.35, Λ_hd = 3.05,
/// Kragelsky boundary friction, film (2.17)) and the hydrodynamic law `traction`, every part
/// and contact at the Table 2.4 oil temperature (fully flooded test), misalignment
/// `misalignment_rad` in the load plane.
pub fn obrien_taylor_conditions(
    speed_rpm: f64,
    radial_load_n: f64,
    misalignment_rad: f64,
    traction: NviTraction,
) -> QuasiStaticConditions {
    let mut oil = lubricant_by_name("nvi65").expect("built-in oil");
    let t = celsius(obrien_taylor_temperature_c(speed_rpm));
    let friction = match traction {
        NviTraction::Seed000Elastic => FrictionModel::seed000_nvi65(),
        NviTraction::MaxwellEyring { tau0_pa } => {
            oil.eyring_stress = Some(TempLaw::Constant { value: tau0_pa });
            FrictionModel::Muraki {
                settings: MurakiSettings {
                    rheology: Rheology::Isothermal,
                    ..MurakiSettings::default()
                },
                mixed: Some(MixedLimits::NVI65),
                film: FilmFormula::Auto,
            }
        }
    };
    let mut c = QuasiStaticConditions::new(rpm(speed_rpm), 0.0, radial_load_n, oil, t);
    c.friction = friction;
    c.misalignment_rad = Some(misalignment_rad);
    c
}

/// One point of the O'Brien–Taylor study.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StudyRow {
    /// Inner-ring speed, rpm.
    pub inner_speed_rpm: f64,
    /// Outer-ring speed, rpm.
    pub outer_speed_rpm: f64,
    /// Radial load, N.
    pub radial_load_n: f64,
    /// Misalignment, arc minutes.
    pub misalignment_arcmin: f64,
    /// Oil temperature, °C.
    pub temperature_c: f64,
    /// Cage slip ε₀ (`None` if the point failed).
    pub cage_slip: Option<f64>,
    /// Cage speed, rad/s.
    pub cage_speed_rad_s: Option<f64>,
    /// Epicyclic cage speed, rad/s.
    pub epicyclic_cage_speed_rad_s: f64,
    /// Largest roller load, N.
    pub max_roller_load_n: Option<f64>,
    /// Largest |slide-to-roll ratio| of the inner contacts.
    pub max_inner_slide_roll: Option<f64>,
    /// Largest |roller slip| on the outer (driving for intershaft) raceway.
    pub max_outer_slide_roll: Option<f64>,
    /// Operating clearance, m.
    pub operating_clearance_m: Option<f64>,
    /// Total friction power, W.
    pub power_loss_w: Option<f64>,
    /// Error message of a failed point.
    pub error: Option<String>,
}

fn row(
    bearing: &CylindricalRollerBearing,
    n_i: f64,
    n_o: f64,
    load: f64,
    mis_arcmin: f64,
    t_c: f64,
    r: Result<crate::SkidResult, crate::QsError>,
) -> StudyRow {
    match r {
        Ok(r) => StudyRow {
            inner_speed_rpm: n_i,
            outer_speed_rpm: n_o,
            radial_load_n: load,
            misalignment_arcmin: mis_arcmin,
            temperature_c: t_c,
            cage_slip: Some(r.cage_slip),
            cage_speed_rad_s: Some(r.cage_speed_rad_s),
            epicyclic_cage_speed_rad_s: r.epicyclic_cage_speed_rad_s,
            max_roller_load_n: Some(r.max_roller_load_n),
            max_inner_slide_roll: Some(
                r.rollers
                    .iter()
                    .filter(|x| x.inner.normal_force_n > 0.0)
                    .map(|x| x.inner.slide_roll_ratio.abs())
                    .fold(0.0, f64::max),
            ),
            max_outer_slide_roll: Some(
                r.rollers
                    .iter()
                    .map(|x| x.outer.slide_roll_ratio.abs())
                    .fold(0.0, f64::max),
            ),
            operating_clearance_m: Some(r.operating_clearance_m),
            power_loss_w: Some(r.power_loss_w),
            error: None,
        },
        Err(e) => StudyRow {
            inner_speed_rpm: n_i,
            outer_speed_rpm: n_o,
            radial_load_n: load,
            misalignment_arcmin: mis_arcmin,
            temperature_c: t_c,
            cage_slip: None,
            cage_speed_rad_s: None,
            epicyclic_cage_speed_rad_s: bearing.epicyclic_cage_speed(rpm(n_i), rpm(n_o)),
            max_roller_load_n: None,
            max_inner_slide_roll: None,
            max_outer_slide_roll: None,
            operating_clearance_m: None,
            power_loss_w: None,
            error: Some(e.to_string()),
        },
    }
}

/// The O'Brien–Taylor study (SPEC V-06): for every speed of [`OBRIEN_TAYLOR_SPEEDS_RPM`], cage
/// slip vs the loads of [`OBRIEN_TAYLOR_LOADS_N`] (aligned), then vs the misalignments of
/// [`OBRIEN_TAYLOR_MISALIGNMENTS_ARCMIN`] at 201 N. `bearing` is the model of
/// `examples/obrien-taylor.toml`; the V-06 surface finish is applied
/// ([`obrien_taylor_bearing`]). `drag` gives the drag inputs at an oil temperature (K): the
/// model's, so that the study and the dynamics see the same drag. Every series starts from
/// ε₀ = 0 and is warm-started along the series.
pub fn obrien_taylor(
    bearing: &CylindricalRollerBearing,
    traction: NviTraction,
    options: &QuasiStaticOptions,
    drag: &dyn Fn(f64) -> crate::DragInputs,
) -> Vec<StudyRow> {
    let b = obrien_taylor_bearing(bearing);
    let mut rows = Vec::new();
    for &n in &OBRIEN_TAYLOR_SPEEDS_RPM {
        let t_c = obrien_taylor_temperature_c(n);
        let mut opts = options.clone();
        for &load in &OBRIEN_TAYLOR_LOADS_N {
            let mut c = obrien_taylor_conditions(n, load, 0.0, traction);
            c.drag = drag(celsius(t_c));
            let r = crate::solve(&b, &c, &opts);
            if let Ok(r) = &r {
                opts.initial_cage_slip = r.cage_slip;
            }
            rows.push(row(&b, n, 0.0, load, 0.0, t_c, r));
        }
        let mut opts = options.clone();
        for &m in &OBRIEN_TAYLOR_MISALIGNMENTS_ARCMIN {
            let mut c = obrien_taylor_conditions(n, 201.0, (m / 60.0).to_radians(), traction);
            c.drag = drag(celsius(t_c));
            let r = crate::solve(&b, &c, &opts);
            if let Ok(r) = &r {
                opts.initial_cage_slip = r.cage_slip;
            }
            rows.push(row(&b, n, 0.0, 201.0, m, t_c, r));
        }
    }
    rows
}

// ---------------------------------------------------------------------------------------------
// Intershaft bearing (SPEC V-18, seed 001)
// ---------------------------------------------------------------------------------------------

fn steel() -> Material {
    Material::bearing_steel()
}

/// An intershaft cylindrical roller bearing standing in for 55-2672919Р5 of seed 001, whose
/// geometry the seed does not give (SPEC §1.6 g). Chosen to be typical of a gas-turbine
/// intershaft bearing of that size class (bore series "…19" → Ø95 mm shaft): inner raceway
/// Ø110 mm, 28 rollers Ø11 × 11 mm (crowned 5 µm over 2 mm at each end, 0.3 mm chamfers),
/// outer raceway Ø132 mm (d_m = 121 mm), outer ring Ø150 mm with two guiding ribs Ø127 mm and
/// a total roller–rib clearance of 0.03 mm (seed 001: flat roller ends guided by flat ribs of
/// the outer ring), window cage Ø118.5/Ø126 × 14 mm guided on the outer-ring ribs with a
/// 0.5 mm floating clearance (seed 001: cage centred on the outer-ring lands), mounting radial
/// clearance 0.043 mm (seed 001), Ra 0.2 µm raceways / 0.1 µm rollers. All steel.
pub fn intershaft_bearing() -> CylindricalRollerBearing {
    let roller_len = 11e-3;
    let chamfer = Chamfer {
        axial_length: 0.3e-3,
        radial_height: 0.3e-3,
        radius: 0.5e-3,
    };
    let profile = Profile {
        shape: ProfileShape::Crowned {
            straight_length: 6.4e-3,
            drop: 5e-6,
            crown_radius: None,
        },
        chamfer: Some(chamfer),
        half_length: 0.5 * roller_len,
    };
    let mut roller = Roller {
        diameter: 11e-3,
        length: roller_len,
        profile,
        end_face: EndFace::Flat,
        edge_break: 0.3e-3,
        slice_count: 20,
        material: steel(),
        roughness_ra: 0.1e-6,
        mass_properties: MassProperties::default(),
    };
    roller.mass_properties = roller.computed_mass_properties();
    let rib = |side| Rib {
        side,
        diameter: 127e-3,
        face: RibFace::Flat,
        edge_break: 0.2e-3,
    };
    let mut inner = Ring {
        raceway_diameter: 110e-3,
        body_diameter: 95e-3,
        width: 16e-3,
        ribs: Vec::new(),
        rib_spacing: None,
        raceway_profile: None,
        raceway_wear: None,
        guiding_land: None,
        material: steel(),
        roughness_ra: 0.2e-6,
        mass_properties: MassProperties::default(),
    };
    inner.mass_properties = inner.computed_mass_properties();
    let mut outer = Ring {
        raceway_diameter: 132e-3,
        body_diameter: 150e-3,
        width: 16e-3,
        ribs: vec![rib(RibSide::Left), rib(RibSide::Right)],
        rib_spacing: Some(roller_len + 0.03e-3),
        raceway_profile: None,
        raceway_wear: None,
        guiding_land: Some(GuidingLand {
            diameter: 127e-3,
            width: 2.0e-3,
        }),
        material: steel(),
        roughness_ra: 0.2e-6,
        mass_properties: MassProperties::default(),
    };
    outer.mass_properties = outer.computed_mass_properties();
    let mut cage = Cage {
        guidance: CageGuidance::OuterLand,
        floating_clearance: 0.5e-3,
        // flat faces touching the roller at the pitch circle Ø121 mm, window 11.3 mm there
        pocket: CagePocket {
            faces: PocketFaces::Flat,
            face_clearance: 0.3e-3,
            outer_lip: None,
            inner_lip: None,
            axial: 11.2e-3,
            fillet_radius: 0.0,
        },
        inner_diameter: 116e-3,
        outer_diameter: 126.5e-3,
        width: 15e-3,
        material: steel(),
        plating: None,
        roughness_ra: 0.8e-6,
        mass_properties: MassProperties::default(),
    };
    cage.mass_properties = cage
        .computed_mass_properties(&cage.pocket_context(5.5e-3, 60.5e-3, 28))
        .expect("the intershaft cage's pocket is consistent");
    CylindricalRollerBearing {
        name: "intershaft-example (stand-in for 55-2672919R5)".into(),
        inner_ring: inner,
        outer_ring: outer,
        roller,
        roller_count: 28,
        cage: Some(cage),
        clearance: Clearance {
            radial: 0.043e-3,
            roller_rib_axial: None,
            allow_preload: false,
            radial_is_operating: false,
        },
        misalignment: Misalignment::default(),
    }
}

/// Aviation oil IPM-10 of seed 001 — the seed gives only the name (SPEC §4.2.7), so the data are
/// ASSUMED, typical of a light mineral turbine oil of that grade: ν = 10 mm²/s at 50 °C and
/// 3.2 mm²/s at 100 °C (Walther/ASTM D341 through both), density 860 kg/m³, ᾱ = 1.2e-8 1/Pa,
/// β0 = −d ln η/dT of the viscosity law, K_f = 0.13 W/(m·K); valid 20…150 °C.
pub fn ipm10_assumed() -> Lubricant {
    Lubricant {
        name: "ipm-10 (assumed data)".into(),
        source: "seed 001 names the oil only; typical light mineral turbine oil data (assumed)"
            .into(),
        temperature_range_k: [celsius(20.0), celsius(150.0)],
        density: Some(TempLaw::Constant { value: 860.0 }),
        viscosity: Some(ViscosityLaw::Kinematic {
            law: rolldyn_lubrication::viscosity::walther_from_two_points(
                celsius(50.0),
                10e-6,
                celsius(100.0),
                3.2e-6,
            ),
        }),
        pressure_viscosity: Some(TempLaw::Constant { value: 1.2e-8 }),
        roelands_z: None,
        shear_modulus: None,
        eyring_stress: None,
        beta0_per_k: None,
        kappa_per_k_pa: None,
        thermal_conductivity: Some(TempLaw::Constant { value: 0.13 }),
        mixed_friction: Some(MixedLimitsData {
            lambda_bd: 0.2,
            lambda_hd: 1.5,
        }),
        missing: vec!["everything: assumed values".into()],
    }
}

/// Seed 001 operating point of the intershaft bearing: inner ring at `inner_rpm`, outer ring at
/// `outer_rpm`, radial load `radial_load_n`, ring temperatures 47.3 °C (inner) and 43 °C
/// (outer) (seed 001 V-18), seed 001 friction model, IPM-10 (assumed data).
pub fn intershaft_conditions(
    inner_rpm: f64,
    outer_rpm: f64,
    radial_load_n: f64,
) -> QuasiStaticConditions {
    let mut c = QuasiStaticConditions::new(
        rpm(inner_rpm),
        rpm(outer_rpm),
        radial_load_n,
        ipm10_assumed(),
        celsius(45.0),
    );
    c.temperatures = PartTemperatures::rings(celsius(47.3), celsius(43.0));
    c.friction = FrictionModel::seed001();
    c
}

/// Seed 001 Fig. 3 study: n_н = 13 067 rpm, n_в = 13 067 − rotor slip, radial load
/// `radial_load_n` (the seed's 50 N), for the rotor slips `rotor_slips_rpm` (n_н − n_в).
pub fn intershaft_rotor_slip(
    bearing: &CylindricalRollerBearing,
    rotor_slips_rpm: &[f64],
    radial_load_n: f64,
    options: &QuasiStaticOptions,
) -> Vec<StudyRow> {
    let n_o = 13_067.0;
    let mut opts = options.clone();
    rotor_slips_rpm
        .iter()
        .map(|&ds| {
            let n_i = n_o - ds;
            let c = intershaft_conditions(n_i, n_o, radial_load_n);
            let r = crate::solve(bearing, &c, &opts);
            if let Ok(r) = &r {
                opts.initial_cage_slip = r.cage_slip;
            }
            row(bearing, n_i, n_o, radial_load_n, 0.0, 45.15, r)
        })
        .collect()
}

/// Seed 001 Fig. 6 study: n_в = 5180 rpm, n_н = 11 313 rpm, outer ring at 33 °C, radial loads
/// `loads_n`.
pub fn intershaft_load(
    bearing: &CylindricalRollerBearing,
    loads_n: &[f64],
    options: &QuasiStaticOptions,
) -> Vec<StudyRow> {
    let mut opts = options.clone();
    loads_n
        .iter()
        .map(|&f| {
            let mut c = intershaft_conditions(5180.0, 11_313.0, f);
            c.temperatures = PartTemperatures::rings(celsius(47.3), celsius(33.0));
            let r = crate::solve(bearing, &c, &opts);
            if let Ok(r) = &r {
                opts.initial_cage_slip = r.cage_slip;
            }
            row(bearing, 5180.0, 11_313.0, f, 0.0, 40.15, r)
        })
        .collect()
}
