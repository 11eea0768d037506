//! Marker types naming the dimension of a [`Quantity`](crate::Quantity) at compile time.

use crate::unit_table::Dimension;

/// A compile-time dimension marker.
pub trait Dim: Copy + Clone + std::fmt::Debug + PartialEq + 'static {
    const DIMENSION: Dimension;
}

macro_rules! markers {
    ($($name:ident),* $(,)?) => {$(
        #[doc = concat!("Marker for `Dimension::", stringify!($name), "`.")]
        #[derive(Debug, Clone, Copy, PartialEq)]
        pub struct $name;
        impl Dim for $name {
            const DIMENSION: Dimension = Dimension::$name;
        }
    )*};
}

markers!(
    Dimensionless,
    Length,
    Area,
    Mass,
    Time,
    Force,
    Moment,
    Pressure,
    Angle,
    AngularSpeed,
    Speed,
    Acceleration,
    Temperature,
    DynamicViscosity,
    KinematicViscosity,
    Density,
    Stiffness,
    Damping,
    Power,
    Energy,
    Frequency,
    ThermalConductivity,
    SpecificHeat,
    RotationalDamping,
    PerTemperature,
    PerPressure,
    PerArea,
    Inertia,
);
