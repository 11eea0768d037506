//! Overrides of a model's `[operating]` section for the analyses that run the dynamics or the
//! load distribution of one operating point (`simulate`, `bench`, `wear`, `fatigue`, `loads`),
//! and the length of a dynamics run.

use rolldyn_setup::{LoadDirection, Overrides};
use rolldyn_units::{Angle, AngularSpeed, Force, Quantity, Temperature, Time};
use serde::de::{self, Deserializer};
use serde::{Deserialize, Serialize};
use std::str::FromStr;

/// Whether the radial load stands still or turns with the inner ring.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum LoadDirectionName {
    Fixed,
    Rotating,
}

/// The operating point's overrides; each `None` keeps the model's value.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Operating {
    /// Inner-ring speed (operating.inner_speed).
    pub speed: Option<Quantity<AngularSpeed>>,
    /// Outer-ring speed (intershaft bearings).
    pub outer_speed: Option<Quantity<AngularSpeed>>,
    /// Radial load on the inner ring (operating.radial_load).
    pub radial_load: Option<Quantity<Force>>,
    /// Axial load on the inner ring along +z (operating.axial_load; tapered bearings).
    pub axial_load: Option<Quantity<Force>>,
    pub load_direction: Option<LoadDirectionName>,
    /// Oil temperature of all contacts (operating.temperatures.oil).
    pub oil_temperature: Option<Quantity<Temperature>>,
    /// Inner-ring misalignment (misalignment.inner_ring).
    pub misalignment: Option<Quantity<Angle>>,
}

impl Operating {
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
                LoadDirectionName::Fixed => LoadDirection::Fixed,
                LoadDirectionName::Rotating => LoadDirection::Rotating,
            }),
            oil_temperature: self.oil_temperature.map(|q| q.si()),
            misalignment: self.misalignment.map(|q| q.si()),
        }
    }
}

/// How long to simulate: cage revolutions (`"20rev"`) or a time (`"0.2s"`, `"50ms"`, or a
/// number of seconds).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum Duration {
    CageRevolutions(f64),
    Time(f64),
}

impl FromStr for Duration {
    type Err = String;
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        let text = text.trim();
        let duration = match text.strip_suffix("rev") {
            Some(n) => Duration::CageRevolutions(
                n.trim()
                    .parse()
                    .map_err(|_| format!("'{text}': expected e.g. 20rev or 0.2s"))?,
            ),
            None if text.parse::<f64>().is_ok() => {
                return Err(format!(
                    "'{text}' has no unit: give cage revolutions or a time, e.g. {text}rev or {text}s"
                ));
            }
            None => Duration::Time(
                Quantity::<Time>::parse(text)
                    .map_err(|e| e.to_string())?
                    .si(),
            ),
        };
        duration.checked(text)
    }
}

impl Duration {
    fn checked(self, text: &str) -> Result<Self, String> {
        match self {
            Duration::CageRevolutions(v) | Duration::Time(v) if v > 0.0 && v.is_finite() => {
                Ok(self)
            }
            _ => Err(format!("'{text}': the duration must be positive")),
        }
    }
}

impl Duration {
    /// The end time for a cage revolution period `revolution` [s] (`None`: the rings start at
    /// rest, and a number of revolutions is no duration).
    pub fn end_time(self, revolution: Option<f64>) -> Result<f64, String> {
        match (self, revolution) {
            (Duration::CageRevolutions(n), Some(period)) => Ok(n * period),
            (Duration::CageRevolutions(_), None) => Err(
                "the inner ring starts at rest (operating.speed_schedule): give --duration as a time, e.g. 0.5s, or a constant --speed".into(),
            ),
            (Duration::Time(t), _) => Ok(t),
        }
    }
}

impl<'de> Deserialize<'de> for Duration {
    /// A string as on the command line, or a number of seconds.
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        seconds_or_text(deserializer, |s| Duration::Time(s).checked(&s.to_string()))
    }
}

/// A value given as a number of seconds (`seconds` makes it) or as its command-line text
/// (`FromStr`): the request form of a duration or a period.
pub fn seconds_or_text<'de, D, T>(
    deserializer: D,
    seconds: impl FnOnce(f64) -> Result<T, String>,
) -> Result<T, D::Error>
where
    D: Deserializer<'de>,
    T: FromStr<Err = String>,
{
    #[derive(Deserialize)]
    #[serde(untagged)]
    enum Given {
        Seconds(f64),
        Text(String),
    }
    match Given::deserialize(deserializer)? {
        Given::Seconds(s) => seconds(s),
        Given::Text(t) => t.parse(),
    }
    .map_err(de::Error::custom)
}

/// Parallel jobs: the number asked for, or the number of cores.
pub fn jobs_or_cores(jobs: Option<usize>) -> usize {
    jobs.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
}
