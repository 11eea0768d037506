//! # rolldyn-lubrication — lubricant properties, film thickness, traction and scuffing (SPEC §4)
//!
//! Pure, allocation-free-at-runtime physics functions for the lubricated contacts of a roller
//! bearing. SI units everywhere in the API (m, N, Pa, Pa·s, m²/s, K, W). Temperatures are
//! **kelvin** in the API; the seed correlations that are written in °C (PAO1, NVI 65 fits) are
//! evaluated internally with θ = T − 273.15 and say so in their docs.
//!
//! ## Map of the crate
//! | module | content | SPEC |
//! |---|---|---|
//! | [`lubricant`] | [`Lubricant`] (serde-deserialisable user oils), temperature laws, [`SolidThermal`] | §4.1, §4.2 |
//! | [`library`] | built-in oils, looked up by name ([`lubricant_by_name`]) | §4.2 |
//! | [`grades`] | ISO VG grades (mineral, PAO), aero-engine and gear oils | — |
//! | [`provenance`] | measured / estimated and the source of each property | — |
//! | [`viscosity_index`] | ASTM D2270 viscosity index and its inverse | — |
//! | [`correlations`] | Wooster ᾱ, Cragoe K_f, density from 15 °C | — |
//! | [`viscosity`] | Walther/ASTM D341 fit, Barus and Roelands pressure–viscosity | §4.1, §4.2.5 |
//! | [`contact_state`] | [`ContactState`]: the operating point of one contact (slice); Hertz (2.15)/(2.16) | §2.3, §4.6 |
//! | [`film`] | film-thickness formulas (2.17), (2.19), seed 001, Pan–Hamrock, Hamrock–Dowson | §4.7 |
//! | [`regime`] | Λ (1.2) / Tallian, G1/G2 (1.10)–(1.11), regime enums | §4.3, §4.7 |
//! | [`mod@traction`] | **the single entry point [`traction()`]**, Muraki (1.4)–(1.9), mixed (1.3), boundary (2.10), seed 001 asperity + Blok flash model, two-level STEP law | §3.4, §4.4–4.6, §4.9 |
//! | [`scuffing`] | critical slip s_cr (bracket + Brent), margin, dN/ds diagnostics (2.21)–(2.32) | §4.8 |
//! | [`mixture`] | air–oil mixture density (seed 001) and seed 000 mixture rules | §4.10, §3.6 |
//!
//! ## Quick start
//! ```
//! use rolldyn_lubrication::*;
//! let oil = lubricant_by_name("pao1-vg320").unwrap();
//! let model = TractionModel::muraki(oil).unwrap();
//! // ball Ø19 mm on a flat disc, 35 N (p_max ≈ 1 GPa), u = 2.5 m/s, 5 % slip, 40 °C
//! let state = ContactState {
//!     normal_force_n: 35.0,
//!     geometry: ContactGeometry::Circular,
//!     reduced_radius_m: 0.0095,
//!     reduced_modulus_pa: 2.0 * 210e9 / (2.0 * (1.0 - 0.09)),
//!     rolling_speed_m_s: 2.5,
//!     sliding_speed_m_s: 0.05 * 2.5,
//!     temperature_k: 313.15,
//!     roughness_ra_m: [0.0, 0.0],
//!     film_thickness_m: None,
//! };
//! let t = traction(&state, &model);
//! assert!(t.coefficient > 0.03 && t.coefficient < 0.06);
//! ```

#![warn(missing_docs)]

pub mod contact_state;
pub mod correlations;
mod error;
pub mod film;
pub mod grades;
pub mod library;
pub mod lubricant;
pub mod mixture;
pub mod plausible;
pub mod provenance;
pub mod regime;
pub mod scuffing;
mod seed_rheology;
mod special;
pub mod traction;
pub mod viscosity;
pub mod viscosity_index;

pub use contact_state::{ContactGeometry, ContactState, HertzContact};
pub use error::LubError;
pub use film::{FilmFormula, FilmResult, FilmSettings};
pub use library::{KNOWN_OILS, lubricant_by_name};
pub use lubricant::{Lubricant, OilProperties, SolidThermal, TempLaw, ViscosityLaw};
pub use provenance::{Basis, OilProperty, PropertySource};
pub use regime::{FrictionRegime, LambdaDefinition, LubricationRegime};
pub use scuffing::{CriticalSlip, SlipSearch, critical_slip};
pub use traction::{
    BatchContact, BoundaryFriction, FrictionLaw, Hydrodynamic, LubricatedFriction, MixedLimits,
    MurakiSettings, PreparedContact, Rheology, Seed001Settings, SliceBatch, SliceColumnsMut,
    SmallShearRate, Traction, TractionModel, TwoLevelLaw, Warnings, traction,
};
