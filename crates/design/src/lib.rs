//! A single-row cylindrical roller bearing from its designation or boundary dimensions: the ISO 15
//! boundary dimensions ([`iso15`]), the ISO 5753-1 radial clearance ([`iso5753`]) and the internal
//! geometry by design rules ([`rules`]), written as a rolldyn model file ([`model_file`]) with
//! every estimated value marked `# ESTIMATED: rule, source` (docs/theory.md, "A model from a
//! designation").
//!
//! Lengths are in metres, speeds in rad/s, forces in N, temperatures in K.

// Validation reads `!(x > 0.0)` on purpose: it is also true for NaN, which must be rejected.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod designation;
pub mod iso15;
pub mod iso5753;
pub mod model_file;
pub mod rules;

pub use designation::{Designation, RibArrangement};
pub use iso5753::ClearanceGroup;
pub use rules::{BearingDesign, design};

/// The cage materials `rolldyn new` offers, by the built-in material each uses.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum CageMaterial {
    /// Machined brass CuZn40Pb2 (`cuzn40pb2`).
    #[default]
    Brass,
    /// Machined steel AISI 4340 (`aisi-4340`).
    Steel,
    /// PEEK (`peek`).
    Peek,
    /// Glass-fibre reinforced polyamide PA66-GF25 (`pa66-gf25`).
    Pa66,
}

impl CageMaterial {
    /// The built-in material name of the model file.
    pub fn material(self) -> &'static str {
        match self {
            Self::Brass => "cuzn40pb2",
            Self::Steel => "aisi-4340",
            Self::Peek => "peek",
            Self::Pa66 => "pa66-gf25",
        }
    }

    /// How the cage is made, for the file's comment.
    pub fn description(self) -> &'static str {
        match self {
            Self::Brass => "machined brass window cage",
            Self::Steel => "machined steel window cage",
            Self::Peek => "PEEK window cage",
            Self::Pa66 => "glass-fibre reinforced polyamide window cage",
        }
    }
}

/// The boundary dimensions of the bearing and where they come from.
#[derive(Clone, Debug, PartialEq)]
pub struct Boundary {
    pub bore: f64,
    pub outside: f64,
    pub width: f64,
    /// ISO 15 r_s min; `None`: taken from the nearest tabulated row (estimated).
    pub chamfer_min: Option<f64>,
    /// Evidence for d, D, B (an ISO 15 table, or "given").
    pub source: String,
}

/// The operating point to write as `[operating]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OperatingPoint {
    /// Inner-ring speed, rad/s (outer ring fixed).
    pub speed: f64,
    /// Radial load, N.
    pub radial_load: f64,
    /// Oil temperature, K; `None`: the generator's assumed value, named in the file and in the
    /// warnings.
    pub oil_temperature: Option<f64>,
}

/// The oil a model gets when none is asked for: an ISO VG 68 mineral oil, the usual circulating
/// oil of medium-speed industrial bearings; written ASSUMED, the user should name theirs.
pub const ASSUMED_OIL: &str = "iso-vg-68-mineral";

impl DesignInput {
    /// The oil written into the model.
    pub fn oil_name(&self) -> &str {
        self.oil.as_deref().unwrap_or(ASSUMED_OIL)
    }
}

/// Everything the generator takes.
#[derive(Clone, Debug, PartialEq)]
pub struct DesignInput {
    pub name: String,
    pub ribs: RibArrangement,
    pub boundary: Boundary,
    /// Catalogue values, when known (they replace the design rules).
    pub roller_diameter: Option<f64>,
    pub roller_length: Option<f64>,
    pub rollers: Option<usize>,
    pub cage: CageMaterial,
    pub clearance_group: ClearanceGroup,
    /// A built-in oil name; `None`: [`ASSUMED_OIL`], named in the file and in the warnings.
    pub oil: Option<String>,
    pub operating: Option<OperatingPoint>,
}

/// Why no bearing can be designed: the input named (`flag`, as the command line spells it)
/// and the reason.
#[derive(Clone, Debug, PartialEq)]
pub struct DesignError {
    pub input: &'static str,
    pub reason: String,
}

impl std::fmt::Display for DesignError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} — {}", self.input, self.reason)
    }
}

impl std::error::Error for DesignError {}

impl DesignError {
    pub fn new(input: &'static str, reason: impl Into<String>) -> Self {
        Self {
            input,
            reason: reason.into(),
        }
    }
}
