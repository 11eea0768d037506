//! Command-line overrides of a model's `[operating]` section, shared by the commands that run
//! the dynamics of one operating point (`simulate`, `bench`, `wear`, `fatigue`).

use rolldyn::operating::{LoadDirectionName, Operating};
use rolldyn_units::{Angle, AngularSpeed, Force, Quantity, Temperature};

#[derive(clap::Args)]
pub struct OperatingArgs {
    /// Inner-ring speed (overrides operating.inner_speed).
    #[arg(long, allow_hyphen_values = true)]
    pub speed: Option<Quantity<AngularSpeed>>,
    /// Outer-ring speed (intershaft bearings).
    #[arg(long, allow_hyphen_values = true)]
    pub outer_speed: Option<Quantity<AngularSpeed>>,
    /// Radial load on the inner ring (overrides operating.radial_load).
    #[arg(long, allow_hyphen_values = true)]
    pub radial_load: Option<Quantity<Force>>,
    /// Axial load on the inner ring along +z (overrides operating.axial_load; tapered bearings).
    #[arg(long, allow_hyphen_values = true)]
    pub axial_load: Option<Quantity<Force>>,
    /// Radial load fixed in space or rotating with the inner ring.
    #[arg(long, value_enum)]
    pub load_direction: Option<LoadDirectionName>,
    /// Oil temperature of all contacts (overrides operating.temperatures.oil).
    #[arg(long, allow_hyphen_values = true)]
    pub oil_temperature: Option<Quantity<Temperature>>,
    /// Inner-ring misalignment, e.g. 11arcmin (overrides misalignment.inner_ring).
    #[arg(long, allow_hyphen_values = true)]
    pub misalignment: Option<Quantity<Angle>>,
}

impl OperatingArgs {
    /// The overrides as the library takes them.
    pub fn operating(&self) -> Operating {
        Operating {
            speed: self.speed,
            outer_speed: self.outer_speed,
            radial_load: self.radial_load,
            axial_load: self.axial_load,
            load_direction: self.load_direction,
            oil_temperature: self.oil_temperature,
            misalignment: self.misalignment,
        }
    }

    /// Whether any override is given.
    pub fn any(&self) -> bool {
        self.operating().any()
    }

    /// The overrides in SI.
    pub fn overrides(&self) -> rolldyn_setup::Overrides {
        self.operating().overrides()
    }
}
