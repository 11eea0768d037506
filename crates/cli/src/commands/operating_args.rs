//! Command-line overrides of a model's `[operating]` section, shared by the commands that run
//! the dynamics of one operating point (`simulate`, `bench`, `wear`, `fatigue`).

use rolldyn_setup::{LoadDirection, Overrides};
use rolldyn_units::{Angle, AngularSpeed, Force, Quantity, Temperature};

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum LoadDirectionArg {
    Fixed,
    Rotating,
}

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
    pub load_direction: Option<LoadDirectionArg>,
    /// Oil temperature of all contacts (overrides operating.temperatures.oil).
    #[arg(long, allow_hyphen_values = true)]
    pub oil_temperature: Option<Quantity<Temperature>>,
    /// Inner-ring misalignment, e.g. 11arcmin (overrides misalignment.inner_ring).
    #[arg(long, allow_hyphen_values = true)]
    pub misalignment: Option<Quantity<Angle>>,
}

impl OperatingArgs {
    /// Whether any override is given.
    pub fn any(&self) -> bool {
        self.speed.is_some()
            || self.outer_speed.is_some()
            || self.radial_load.is_some()
            || self.axial_load.is_some()
            || self.load_direction.is_some()
            || self.oil_temperature.is_some()
            || self.misalignment.is_some()
    }

    /// The overrides in SI.
    pub fn overrides(&self) -> Overrides {
        Overrides {
            speed: self.speed.map(|q| q.si()),
            outer_speed: self.outer_speed.map(|q| q.si()),
            radial_load: self.radial_load.map(|q| q.si()),
            axial_load: self.axial_load.map(|q| q.si()),
            load_direction: self.load_direction.map(|d| match d {
                LoadDirectionArg::Fixed => LoadDirection::Fixed,
                LoadDirectionArg::Rotating => LoadDirection::Rotating,
            }),
            oil_temperature: self.oil_temperature.map(|q| q.si()),
            misalignment: self.misalignment.map(|q| q.si()),
        }
    }
}
