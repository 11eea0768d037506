//! Physical dimensions: the runtime [`Dimension`](crate::Dimension) enum and the compile-time
//! marker types naming the dimension of a [`Quantity`](crate::Quantity), generated together.

use std::fmt;

/// A compile-time dimension marker.
pub trait Dim: Copy + Clone + std::fmt::Debug + PartialEq + 'static {
    const DIMENSION: Dimension;
}

/// Declares every dimension once: the `Dimension` enum with its human name and SI symbol, and
/// one marker type per dimension.
macro_rules! dimensions {
    ($($name:ident => $human:literal, $si:literal;)*) => {
        /// A physical dimension a quantity can have.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum Dimension {
            $($name,)*
        }

        impl Dimension {
            /// Human name used in error messages.
            pub fn name(self) -> &'static str {
                match self {
                    $(Self::$name => $human,)*
                }
            }

            /// SI unit symbol, used when a plain number is given and in messages.
            pub fn si_symbol(self) -> &'static str {
                match self {
                    $(Self::$name => $si,)*
                }
            }
        }

        /// Compile-time markers, one per [`Dimension`].
        pub mod markers {
            $(
                #[doc = concat!("Marker for ", $human, " (", $si, ").")]
                #[derive(Debug, Clone, Copy, PartialEq)]
                pub struct $name;
                impl super::Dim for $name {
                    const DIMENSION: super::Dimension = super::Dimension::$name;
                }
            )*
        }
    };
}

dimensions! {
    Dimensionless => "a dimensionless number", "";
    Length => "a length", "m";
    Area => "an area", "m²";
    Mass => "a mass", "kg";
    Time => "a time", "s";
    Force => "a force", "N";
    Moment => "a moment", "N m";
    Pressure => "a pressure", "Pa";
    Angle => "an angle", "rad";
    AngularSpeed => "an angular speed", "rad/s";
    Speed => "a speed", "m/s";
    Acceleration => "an acceleration", "m/s²";
    Temperature => "a temperature", "K";
    DynamicViscosity => "a dynamic viscosity", "Pa s";
    KinematicViscosity => "a kinematic viscosity", "m²/s";
    Density => "a density", "kg/m³";
    Stiffness => "a stiffness", "N/m";
    LoadPerLength => "a load per unit length", "N/m";
    Damping => "a damping coefficient", "N s/m";
    Power => "a power", "W";
    Energy => "an energy", "J";
    Frequency => "a frequency", "Hz";
    ThermalConductivity => "a thermal conductivity", "W/(m K)";
    SpecificHeat => "a specific heat", "J/(kg K)";
    RotationalDamping => "a rotational damping coefficient", "N m s/rad";
    PerTemperature => "a temperature coefficient", "1/K";
    PerPressure => "a pressure coefficient", "1/Pa";
    PerArea => "an inverse area", "1/m²";
    Inertia => "a moment of inertia", "kg m²";
    Unbalance => "an unbalance (mass × eccentricity)", "kg m";
}

impl fmt::Display for Dimension {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
