//! The contact a lubrication command evaluates: a ball on a disc (the PAO1 traction rig of
//! seed 000 §2.2) or a line contact (roller on raceway), with its elastic data.

use rolldyn::oil::{ContactKind, Rig};
use rolldyn_units::{Dimensionless, Length, Pressure, Quantity};

#[derive(clap::Args)]
pub struct RigArgs {
    #[arg(long, value_enum, default_value = "ball-on-disc")]
    pub contact: ContactKind,
    /// Ball radius (ball-on-disc) or reduced radius R′ (line). Default: the Ø19 mm ball of the
    /// seed's PAO1 tests.
    #[arg(long, allow_hyphen_values = true, default_value = "9.5mm")]
    pub radius: Quantity<Length>,
    /// Contact length of a line contact.
    #[arg(long, allow_hyphen_values = true, default_value = "10mm")]
    pub length: Quantity<Length>,
    /// Young's modulus of both bodies (AISI 52100).
    #[arg(long, allow_hyphen_values = true, default_value = "210GPa")]
    pub youngs_modulus: Quantity<Pressure>,
    /// Poisson's ratio of both bodies.
    #[arg(long, allow_hyphen_values = true, default_value = "0.3")]
    pub poisson_ratio: Quantity<Dimensionless>,
}

impl RigArgs {
    /// The test contact.
    pub fn rig(&self) -> Rig {
        Rig {
            contact: self.contact,
            radius: self.radius,
            length: self.length,
            youngs_modulus: self.youngs_modulus,
            poisson_ratio: self.poisson_ratio,
        }
    }
}
