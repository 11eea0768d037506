//! The built-in materials (docs/theory.md §10.5, docs/model-format.md `[materials]`): bearing
//! steels and cage materials, each one record with E, ν, density, hardness, ultimate strength and
//! a fully reversed S–N curve, every value with its source. What is estimated says so, with its
//! rule. A model part names an entry (`material = "cuzn40pb2"`) without a `[materials]` table.

use crate::material::{
    FatigueStrength, Material, PA_PER_KGF_PER_MM2, meyer_from_vickers, vickers_from_meyer,
};

const GPA: f64 = 1e9;
const MPA: f64 = 1e6;

/// A hardness as its source states it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Hardness {
    /// Vickers number HV (kgf/mm²).
    Vickers(f64),
    /// Meyer hardness, Pa.
    Meyer(f64),
}

impl Hardness {
    /// Meyer hardness, Pa (HV → Meyer by [`meyer_from_vickers`]).
    pub fn meyer_pa(self) -> f64 {
        match self {
            Hardness::Vickers(hv) => meyer_from_vickers(hv),
            Hardness::Meyer(pa) => pa,
        }
    }

    /// Vickers number HV (kgf/mm²).
    pub fn vickers(self) -> f64 {
        match self {
            Hardness::Vickers(hv) => hv,
            Hardness::Meyer(pa) => vickers_from_meyer(pa),
        }
    }
}

/// A Basquin line σ_a = σ_ref (N / N_ref)^b, tabulated per decade of N from `first_cycles` to the
/// knee at `knee_cycles` (both whole powers of ten).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Basquin {
    /// `(N_ref, σ_ref [Pa])`, a point of the line
    pub reference: (f64, f64),
    /// b = d lg σ_a / d lg N
    pub exponent: f64,
    pub first_cycles: f64,
    pub knee_cycles: f64,
}

impl Basquin {
    /// The line through `first` and `knee`, both `(N, σ_a [Pa])`, tabulated between them.
    pub fn through(first: (f64, f64), knee: (f64, f64)) -> Self {
        Self {
            reference: first,
            exponent: (knee.1 / first.1).log10() / (knee.0 / first.0).log10(),
            first_cycles: first.0,
            knee_cycles: knee.0,
        }
    }

    /// The table `(N, σ_a [Pa])`, one point per decade.
    pub fn points(&self) -> Vec<(f64, f64)> {
        let decade = |n: f64| n.log10().round() as i32;
        let (n_ref, s_ref) = self.reference;
        (decade(self.first_cycles)..=decade(self.knee_cycles))
            .map(|lg_n| {
                let n = 10f64.powi(lg_n);
                let ratio = n / n_ref;
                (n, s_ref * ratio.powf(self.exponent))
            })
            .collect()
    }
}

/// The ultimate strength σ_u [Pa] of a steel from its Vickers number by the correlation of
/// Pavlina E. J., Van Tyne C. J., "Correlation of yield strength and tensile strength with
/// hardness for steels", J. Mater. Eng. Perform. 17 (2008) 888–893: σ_u = −99.8 + 3.734 HV MPa.
pub fn steel_ultimate_strength_from_vickers(vickers: f64) -> f64 {
    (-99.8 + 3.734 * vickers) * MPA
}

/// The inverse of [`steel_ultimate_strength_from_vickers`]: HV of a steel of σ_u [Pa].
pub fn steel_vickers_from_ultimate_strength(ultimate_pa: f64) -> f64 {
    (ultimate_pa / MPA + 99.8) / 3.734
}

/// The generalised bending S–N curve of a steel without test data (ESTIMATED): 0.9 σ_u at 10³
/// cycles and the fatigue limit S'_e = 0.5 σ_u, at most 700 MPa, at 10⁶ (Budynas R. G., Nisbett
/// J. K., *Shigley's Mechanical Engineering Design*, 10th ed., eq. 6-8; Juvinall R. C., Marshek
/// K. M., *Fundamentals of Machine Component Design*, the bending S–N curve of steel).
pub fn estimated_steel_curve(ultimate_pa: f64) -> Basquin {
    let endurance = (0.5 * ultimate_pa).min(700.0 * MPA);
    Basquin::through((1e3, 0.9 * ultimate_pa), (1e6, endurance))
}

/// The S–N curve of a material without a fatigue limit from its endurance ratio (ESTIMATED): 0.9
/// σ_u at 10³ cycles and `endurance_ratio` · σ_u at `knee_cycles`, below which no damage is
/// counted unless the fatigue run asks otherwise.
pub fn estimated_curve_from_endurance_ratio(
    ultimate_pa: f64,
    endurance_ratio: f64,
    knee_cycles: f64,
) -> Basquin {
    Basquin::through(
        (1e3, 0.9 * ultimate_pa),
        (knee_cycles, endurance_ratio * ultimate_pa),
    )
}

/// Seed 000 §3.1.1.8: 40KhN2MA-Sh at 100 °C reaches 10⁶ cycles at σ_a = 480 MPa, R = −1.
pub const SEED_FATIGUE_STRENGTH_PA: f64 = 480e6;
/// The life at [`SEED_FATIGUE_STRENGTH_PA`].
pub const SEED_FATIGUE_STRENGTH_CYCLES: f64 = 1e6;
/// Basquin exponent b of AISI 4340 (aircraft quality, σ_u 1172 MPa), σ_a = A N^b from unnotched
/// axial tests at zero mean stress: Dowling N. E., *Mechanical Behavior of Materials*, 4th ed.,
/// Pearson 2013, Table 9.1 (b = B = −0.0977).
pub const AISI_4340_BASQUIN_EXPONENT: f64 = -0.0977;
/// Ultimate tensile strength of the same AISI 4340 (Dowling 2013, Table 9.1: 1172 MPa).
pub const AISI_4340_ULTIMATE_STRENGTH_PA: f64 = 1172e6;
/// The knee of the steel curves from Basquin constants: 10⁷ cycles, the test base of the fatigue
/// limit of steels (a rolldyn choice; neither the seed nor Dowling gives a knee).
pub const AISI_4340_KNEE_CYCLES: f64 = 1e7;
/// The first point of those tables (the low-cycle side beyond it extrapolates).
pub const AISI_4340_FIRST_CYCLES: f64 = 1e3;

/// Dowling 2013, Table 9.1, AISI 4340 aircraft quality: A = 1643 MPa in σ_a = A N^B.
const AISI_4340_BASQUIN_COEFFICIENT_PA: f64 = 1643e6;

/// MMPDS (Metallic Materials Properties Development and Standardization), §2.3.1, the low-alloy
/// steels 4130/4140/4340: E = 29.0·10³ ksi, μ = 0.32, ω = 0.283 lb/in³.
const MMPDS_LOW_ALLOY_STEEL: &str =
    "MMPDS §2.3.1 (low-alloy steels): E = 29.0e3 ksi = 200 GPa, ν = 0.32, ρ = 0.283 lb/in³";

/// A built-in material with the source of each value.
#[derive(Debug, Clone, PartialEq)]
pub struct MaterialRecord {
    /// the name a model uses (lowercase)
    pub name: &'static str,
    /// other names of the same entry
    pub aliases: &'static [&'static str],
    pub description: &'static str,
    /// E, Pa
    pub youngs_modulus: f64,
    pub poisson_ratio: f64,
    /// ρ, kg/m³
    pub density: f64,
    /// `None` where the source gives no scale convertible to HV (the polymers' Rockwell M)
    pub hardness: Option<Hardness>,
    /// σ_u, Pa
    pub ultimate_strength: f64,
    pub sn_curve: Basquin,
    /// `(quantity, source)`; an estimated value's source starts with `ESTIMATED:`
    pub sources: Vec<(&'static str, String)>,
}

impl Material {
    /// Through-hardened bearing steel (AISI 52100 / ШХ15), the database entry `bearing-steel`.
    pub fn bearing_steel() -> Self {
        find("bearing-steel")
            .expect("the database holds bearing-steel")
            .material()
    }
}

impl MaterialRecord {
    /// The record as the material of a part.
    pub fn material(&self) -> Material {
        Material {
            name: self.name.into(),
            youngs_modulus: self.youngs_modulus,
            poisson_ratio: self.poisson_ratio,
            density: self.density,
            meyer_hardness: self.hardness.map(Hardness::meyer_pa),
            fatigue: Some(FatigueStrength {
                ultimate_strength: self.ultimate_strength,
                sn_curve: self.sn_curve.points(),
                source: format!("{} ({})", self.name, self.source("S–N curve")),
            }),
        }
    }

    /// The source of `quantity` ("" when the record gives none).
    pub fn source(&self, quantity: &str) -> &str {
        self.sources
            .iter()
            .find(|(q, _)| *q == quantity)
            .map_or("", |(_, s)| s.as_str())
    }

    /// The quantities whose value is an estimate.
    pub fn estimated(&self) -> Vec<&'static str> {
        self.sources
            .iter()
            .filter(|(_, s)| s.starts_with("ESTIMATED"))
            .map(|(q, _)| *q)
            .collect()
    }
}

/// Every built-in material, in the order they are listed.
pub fn all() -> Vec<MaterialRecord> {
    vec![
        bearing_steel(),
        seed_cage_steel(),
        aisi_4340(),
        aisi_4140(),
        cuzn40pb2(),
        cual10ni5fe4(),
        peek(),
        pa66_gf25(),
    ]
}

/// The entry called `name` (or with `name` among its aliases).
pub fn find(name: &str) -> Option<MaterialRecord> {
    all()
        .into_iter()
        .find(|r| r.name == name || r.aliases.contains(&name))
}

/// Every name a model may use: the entries' names and aliases.
pub fn names() -> Vec<&'static str> {
    all()
        .iter()
        .flat_map(|r| std::iter::once(r.name).chain(r.aliases.iter().copied()))
        .collect()
}

fn bearing_steel() -> MaterialRecord {
    let hardness = Hardness::Meyer(7.6e9);
    let ultimate = steel_ultimate_strength_from_vickers(hardness.vickers());
    MaterialRecord {
        name: "bearing-steel",
        aliases: &["aisi-52100"],
        description: "through-hardened bearing steel AISI 52100 / 100Cr6 (ISO 683-17) / ШХ15, ≈ 62 HRC",
        youngs_modulus: 208.0 * GPA,
        poisson_ratio: 0.3,
        density: 7830.0,
        hardness: Some(hardness),
        ultimate_strength: ultimate,
        sn_curve: estimated_steel_curve(ultimate),
        sources: vec![
            ("E, ν", "SPEC §1 (208 GPa, 0.3 for 52100 / ШХ15)".into()),
            ("density", "SPEC F-25 (7830 kg/m³)".into()),
            (
                "hardness",
                "SPEC §6.1: Meyer 7.6 GPa ≈ 62 HRC, within the seed's 777…895 kgf/mm² (ISO 683-17 hardened 58…65 HRC)".into(),
            ),
            (
                "ultimate strength",
                "ESTIMATED: from HV by Pavlina & Van Tyne 2008 (σ_u = −99.8 + 3.734 HV MPa)".into(),
            ),
            (
                "S–N curve",
                "ESTIMATED: generalised bending S–N curve of steel, 0.9 σ_u at 10³ and 700 MPa at 10⁶ (Shigley eq. 6-8)".into(),
            ),
        ],
    }
}

fn seed_cage_steel() -> MaterialRecord {
    MaterialRecord {
        name: "40khn2ma-sh",
        aliases: &[],
        description: "the seed's cage steel 40KhN2MA-Sh (40ХН2МА-Ш, GOST 4543, electroslag remelted), silver plated in the seed bearings",
        youngs_modulus: 211.0 * GPA,
        poisson_ratio: 0.3,
        density: 7850.0,
        hardness: Some(Hardness::Meyer(305.0 * PA_PER_KGF_PER_MM2)),
        ultimate_strength: AISI_4340_ULTIMATE_STRENGTH_PA,
        sn_curve: Basquin {
            reference: (SEED_FATIGUE_STRENGTH_CYCLES, SEED_FATIGUE_STRENGTH_PA),
            exponent: AISI_4340_BASQUIN_EXPONENT,
            first_cycles: AISI_4340_FIRST_CYCLES,
            knee_cycles: AISI_4340_KNEE_CYCLES,
        },
        sources: vec![
            ("E, ν", "seed 000 §2.5 (211 GPa at 100 °C, 0.3)".into()),
            ("density", "ESTIMATED: 7850 kg/m³, a low-alloy steel".into()),
            (
                "hardness",
                "seed 000 §3.1.1.5: HB 269 → HV 283 → Meyer 305 kgf/mm² (flag F-45)".into(),
            ),
            (
                "ultimate strength",
                "ESTIMATED: AISI 4340's 1172 MPa (Dowling 2013, Table 9.1); the seed gives none".into(),
            ),
            (
                "S–N curve",
                "seed 000 §3.1.1.8: 480 MPa at 10⁶ cycles, R = −1, 100 °C; slope b = −0.0977 of AISI 4340 (Dowling 2013, Table 9.1), knee at 10⁷ (rolldyn)".into(),
            ),
        ],
    }
}

fn aisi_4340() -> MaterialRecord {
    let ultimate = AISI_4340_ULTIMATE_STRENGTH_PA;
    MaterialRecord {
        name: "aisi-4340",
        aliases: &[],
        description: "AISI 4340 (36CrNiMo4 class) quenched and tempered, aircraft quality",
        youngs_modulus: 200.0 * GPA,
        poisson_ratio: 0.32,
        density: 7833.0,
        hardness: Some(Hardness::Vickers(steel_vickers_from_ultimate_strength(
            ultimate,
        ))),
        ultimate_strength: ultimate,
        sn_curve: Basquin {
            reference: (1.0, AISI_4340_BASQUIN_COEFFICIENT_PA),
            exponent: AISI_4340_BASQUIN_EXPONENT,
            first_cycles: AISI_4340_FIRST_CYCLES,
            knee_cycles: AISI_4340_KNEE_CYCLES,
        },
        sources: vec![
            ("E, ν", MMPDS_LOW_ALLOY_STEEL.into()),
            ("density", MMPDS_LOW_ALLOY_STEEL.into()),
            (
                "hardness",
                "ESTIMATED: from σ_u by Pavlina & Van Tyne 2008 (HV = (σ_u/MPa + 99.8)/3.734)".into(),
            ),
            (
                "ultimate strength",
                "Dowling, Mechanical Behavior of Materials, 4th ed. 2013, Table 9.1 (1172 MPa)".into(),
            ),
            (
                "S–N curve",
                "Dowling 2013, Table 9.1: σ_a = 1643 MPa · N^−0.0977 (unnotched axial tests, R = −1), knee at 10⁷ (rolldyn)".into(),
            ),
        ],
    }
}

fn aisi_4140() -> MaterialRecord {
    let ultimate = 1757.0 * MPA;
    MaterialRecord {
        name: "aisi-4140",
        aliases: &[],
        description: "AISI 4140 (42CrMo4 class) quenched and tempered; strength and S–N of SAE 4142 at 450 HB",
        youngs_modulus: 200.0 * GPA,
        poisson_ratio: 0.32,
        density: 7833.0,
        hardness: Some(Hardness::Vickers(steel_vickers_from_ultimate_strength(
            ultimate,
        ))),
        ultimate_strength: ultimate,
        sn_curve: Basquin {
            reference: (1.0, 1837.0 * MPA),
            exponent: -0.0762,
            first_cycles: AISI_4340_FIRST_CYCLES,
            knee_cycles: AISI_4340_KNEE_CYCLES,
        },
        sources: vec![
            ("E, ν", MMPDS_LOW_ALLOY_STEEL.into()),
            ("density", MMPDS_LOW_ALLOY_STEEL.into()),
            (
                "hardness",
                "ESTIMATED: from σ_u by Pavlina & Van Tyne 2008 (HV = (σ_u/MPa + 99.8)/3.734)".into(),
            ),
            (
                "ultimate strength",
                "ESTIMATED: SAE 4142 Q&T 450 HB (Dowling 2013, Table 9.1: 1757 MPa) standing in for 4140, which differs by 0.02 % C".into(),
            ),
            (
                "S–N curve",
                "ESTIMATED: SAE 4142 Q&T 450 HB, σ_a = 1837 MPa · N^−0.0762 (Dowling 2013, Table 9.1) standing in for 4140, knee at 10⁷ (rolldyn)".into(),
            ),
        ],
    }
}

/// The endurance ratio σ_a(10⁸)/σ_u of wrought brasses and bronzes (ESTIMATED: typically
/// 0.3…0.4; they have no fatigue limit).
const COPPER_ALLOY_ENDURANCE_RATIO: f64 = 0.35;
/// Where the copper alloys' curves stop falling in rolldyn: 10⁸ cycles.
const COPPER_ALLOY_KNEE_CYCLES: f64 = 1e8;
const COPPER_ALLOY_CURVE: &str = "ESTIMATED: 0.9 σ_u at 10³ cycles and 0.35 σ_u at 10⁸ (endurance ratio of wrought copper alloys, typically 0.3…0.4; no fatigue limit, knee put at 10⁸)";

fn cuzn40pb2() -> MaterialRecord {
    let ultimate = 430.0 * MPA;
    MaterialRecord {
        name: "cuzn40pb2",
        aliases: &["cw617n"],
        description: "leaded brass CuZn40Pb2 (CW617N), machined cage from drawn bar",
        youngs_modulus: 96.0 * GPA,
        poisson_ratio: 0.37,
        density: 8430.0,
        hardness: Some(Hardness::Vickers(120.0)),
        ultimate_strength: ultimate,
        sn_curve: estimated_curve_from_endurance_ratio(
            ultimate,
            COPPER_ALLOY_ENDURANCE_RATIO,
            COPPER_ALLOY_KNEE_CYCLES,
        ),
        sources: vec![
            (
                "E, ν",
                "E: Deutsches Kupferinstitut data sheet CuZn40Pb2 (96 GPa); ν ESTIMATED 0.37 (α-β brass)".into(),
            ),
            ("density", "Deutsches Kupferinstitut data sheet CuZn40Pb2 (8.43 g/cm³)".into()),
            (
                "hardness",
                "ESTIMATED: 120 HV, typical of drawn bar of state R430 (EN 12164)".into(),
            ),
            ("ultimate strength", "EN 12164, state R430: R_m ≥ 430 MPa".into()),
            ("S–N curve", COPPER_ALLOY_CURVE.into()),
        ],
    }
}

fn cual10ni5fe4() -> MaterialRecord {
    let ultimate = 680.0 * MPA;
    MaterialRecord {
        name: "cual10ni5fe4",
        aliases: &["cw307g"],
        description: "nickel-aluminium bronze CuAl10Ni5Fe4 (CW307G wrought; cast CC333G of EN 1982 is weaker)",
        youngs_modulus: 120.0 * GPA,
        poisson_ratio: 0.34,
        density: 7600.0,
        hardness: Some(Hardness::Vickers(180.0)),
        ultimate_strength: ultimate,
        sn_curve: estimated_curve_from_endurance_ratio(
            ultimate,
            COPPER_ALLOY_ENDURANCE_RATIO,
            COPPER_ALLOY_KNEE_CYCLES,
        ),
        sources: vec![
            (
                "E, ν",
                "Deutsches Kupferinstitut data sheet CuAl10Ni5Fe4 (E ≈ 120 GPa); ν ESTIMATED 0.34"
                    .into(),
            ),
            (
                "density",
                "Deutsches Kupferinstitut data sheet CuAl10Ni5Fe4 (7.6 g/cm³)".into(),
            ),
            (
                "hardness",
                "ESTIMATED: 180 HV from the HB ≥ 170 of EN 12163 state R680 (HV ≈ 1.05 HB)".into(),
            ),
            (
                "ultimate strength",
                "EN 12163, state R680: R_m ≥ 680 MPa".into(),
            ),
            ("S–N curve", COPPER_ALLOY_CURVE.into()),
        ],
    }
}

/// The endurance ratio σ_a(10⁷)/σ_u of unreinforced and glass-filled thermoplastics
/// (ESTIMATED: a generic value, no fully reversed test data at hand).
const POLYMER_ENDURANCE_RATIO: f64 = 0.3;
const POLYMER_KNEE_CYCLES: f64 = 1e7;
const POLYMER_CURVE: &str = "ESTIMATED: 0.9 σ_u at 10³ cycles and 0.3 σ_u at 10⁷ (a generic endurance ratio of thermoplastics at 23 °C; no fully reversed S–N data at hand)";

fn peek() -> MaterialRecord {
    let ultimate = 98.0 * MPA;
    MaterialRecord {
        name: "peek",
        aliases: &[],
        description: "unreinforced PEEK (Victrex 450G), 23 °C values",
        youngs_modulus: 3.7 * GPA,
        poisson_ratio: 0.40,
        density: 1300.0,
        hardness: None,
        ultimate_strength: ultimate,
        sn_curve: estimated_curve_from_endurance_ratio(
            ultimate,
            POLYMER_ENDURANCE_RATIO,
            POLYMER_KNEE_CYCLES,
        ),
        sources: vec![
            (
                "E, ν",
                "Victrex 450G data sheet (tensile modulus 3.7 GPa, ISO 527, 23 °C); ν ESTIMATED 0.40".into(),
            ),
            ("density", "Victrex 450G data sheet (1.30 g/cm³)".into()),
            (
                "hardness",
                "none: the data sheet gives Rockwell M 99, which has no conversion to Vickers or Meyer".into(),
            ),
            (
                "ultimate strength",
                "Victrex 450G data sheet (tensile strength 98 MPa, ISO 527, 23 °C)".into(),
            ),
            ("S–N curve", POLYMER_CURVE.into()),
        ],
    }
}

fn pa66_gf25() -> MaterialRecord {
    let ultimate = 110.0 * MPA;
    MaterialRecord {
        name: "pa66-gf25",
        aliases: &[],
        description: "polyamide 66 with 25 % glass fibre (e.g. BASF Ultramid A3EG5), conditioned, 23 °C",
        youngs_modulus: 5.6 * GPA,
        poisson_ratio: 0.35,
        density: 1320.0,
        hardness: None,
        ultimate_strength: ultimate,
        sn_curve: estimated_curve_from_endurance_ratio(
            ultimate,
            POLYMER_ENDURANCE_RATIO,
            POLYMER_KNEE_CYCLES,
        ),
        sources: vec![
            (
                "E, ν",
                "ESTIMATED: 5.6 GPa, typical of conditioned PA66-GF25 at 23 °C (about half above its glass transition, examples/tapered-cassette.toml); ν 0.35 typical of glass-filled polyamides".into(),
            ),
            ("density", "BASF Ultramid A3EG5 data sheet (1320 kg/m³)".into()),
            (
                "hardness",
                "none: polyamide data sheets give ball-indentation or Rockwell hardness, no Vickers".into(),
            ),
            (
                "ultimate strength",
                "ESTIMATED: 110 MPa, typical stress at break of conditioned PA66-GF25 at 23 °C (ISO 527)".into(),
            ),
            ("S–N curve", POLYMER_CURVE.into()),
        ],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_entry_has_a_monotone_sn_curve_and_a_unique_name() {
        let names = names();
        for (i, name) in names.iter().enumerate() {
            assert!(!names[i + 1..].contains(name), "{name} twice");
        }
        for record in all() {
            let points = record.sn_curve.points();
            assert!(points.len() >= 2, "{}", record.name);
            assert_eq!(
                crate::material::first_invalid_sn_point(&points),
                None,
                "{}",
                record.name
            );
            assert!(record.sn_curve.points()[0].1 < record.ultimate_strength);
            for quantity in [
                "E, ν",
                "density",
                "hardness",
                "ultimate strength",
                "S–N curve",
            ] {
                assert!(
                    !record.source(quantity).is_empty(),
                    "{} {quantity}",
                    record.name
                );
            }
        }
    }

    #[test]
    fn the_seed_curve_passes_480_mpa_at_a_million_cycles() {
        let curve = find("40khn2ma-sh").unwrap().sn_curve.points();
        assert_eq!(curve[3], (1e6, 480e6));
        assert_eq!(curve.len(), 5);
    }

    #[test]
    fn dowling_4340_constants_give_426_mpa_at_a_million_cycles() {
        // σ_a = 1643 MPa · (10⁶)^−0.0977
        let curve = find("aisi-4340").unwrap().sn_curve.points();
        assert!((curve[3].1 / 1e6 - 426.0).abs() < 0.1, "{:?}", curve[3]);
    }

    #[test]
    fn the_alias_finds_bearing_steel() {
        assert_eq!(find("aisi-52100").unwrap().name, "bearing-steel");
        let hv = find("bearing-steel").unwrap().hardness.unwrap().vickers();
        assert!((hv - 718.4).abs() < 0.1, "{hv}");
    }
}
