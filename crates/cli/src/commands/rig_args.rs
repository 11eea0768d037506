//! The contact a lubrication command evaluates: a ball on a disc (the PAO1 traction rig of
//! seed 000 §2.2) or a line contact (roller on raceway), with its elastic data.

use crate::failure::Failure;
use rolldyn_contact::hertz::reduced_modulus;
use rolldyn_lubrication::ContactGeometry;
use rolldyn_lubrication::contact_state::{
    circular_load_for_max_pressure, line_load_for_max_pressure,
};
use rolldyn_units::{Dimensionless, Length, Pressure, Quantity};

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ContactKind {
    /// Ball on a flat disc (circular point contact; `--radius` is the ball radius).
    BallOnDisc,
    /// Line contact of length `--length`; `--radius` is the reduced radius R′ (seed 000 eq. 1.12).
    Line,
}

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
    /// Validated geometry: (contact geometry, reduced radius R′, reduced modulus E′).
    pub fn geometry(&self) -> Result<(ContactGeometry, f64, f64), Failure> {
        let (r, l) = (self.radius.si(), self.length.si());
        let (e, nu) = (self.youngs_modulus.si(), self.poisson_ratio.si());
        if !(r > 0.0) || !(l > 0.0) || !(e > 0.0) || !(0.0..0.5).contains(&nu) {
            return Err(Failure::Input(
                "--radius, --length and --youngs-modulus must be positive, 0 ≤ --poisson-ratio < 0.5".into(),
            ));
        }
        let geometry = match self.contact {
            ContactKind::BallOnDisc => ContactGeometry::Circular,
            ContactKind::Line => ContactGeometry::Line { length_m: l },
        };
        Ok((geometry, r, reduced_modulus(e, nu, e, nu)))
    }

    /// Normal load giving the maximum Hertz pressure `p_max` on this contact.
    pub fn load_for_max_pressure(&self, p_max: f64) -> Result<f64, Failure> {
        let (geometry, r, e) = self.geometry()?;
        Ok(match geometry {
            ContactGeometry::Line { length_m } => line_load_for_max_pressure(p_max, length_m, e, r),
            _ => circular_load_for_max_pressure(p_max, r, e),
        })
    }
}
