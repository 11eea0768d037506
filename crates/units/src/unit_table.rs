//! The unit symbols rolldyn understands, per physical dimension.

use crate::dimension::Dimension;

impl Dimension {
    /// A few accepted spellings, for error messages.
    /// The unit an error message suggests, the one engineers write most (`mm`, `kN`, `rpm`).
    pub fn example_unit(self) -> &'static str {
        use Dimension::*;
        match self {
            Length => "mm",
            Force => "kN",
            Pressure => "MPa",
            Angle => "deg",
            AngularSpeed => "rpm",
            Temperature => "C",
            KinematicViscosity => "cSt",
            DynamicViscosity => "mPa s",
            Time => "s",
            PerPressure => "1/GPa",
            _ => self.si_symbol(),
        }
    }

    pub fn examples(self) -> &'static str {
        use Dimension::*;
        match self {
            Length => "m, mm, µm (or um), nm",
            Force => "N, kN",
            Pressure => "Pa, MPa, GPa, bar",
            Angle => "rad, deg, arcmin, arcsec",
            AngularSpeed => "rad/s, rpm",
            Temperature => "K, °C (or C, degC)",
            Speed => "m/s, mm/s",
            DynamicViscosity => "Pa s, mPa s, cP",
            KinematicViscosity => "m2/s, mm2/s, cSt",
            Mass => "kg, g",
            Time => "s, ms, us, min, h",
            Density => "kg/m3, g/cm3",
            Stiffness => "N/m, N/mm",
            LoadPerLength => "N/m, kN/m, N/mm, kN/mm, MN/m",
            Damping => "N s/m, N s/mm",
            RotationalDamping => "N m s/rad, N mm/(rad/ms)",
            Unbalance => "kg m, g mm (or g*mm, g·mm), g cm",
            PerPressure => "1/Pa, 1/MPa, 1/GPa (or /Pa, /MPa, /GPa)",
            _ => self.si_symbol(),
        }
    }
}

/// One accepted unit: `si = value * scale + offset`.
pub(crate) struct Unit {
    pub symbol: &'static str,
    pub dimension: Dimension,
    pub scale: f64,
    pub offset: f64,
}

const fn u(symbol: &'static str, dimension: Dimension, scale: f64) -> Unit {
    Unit {
        symbol,
        dimension,
        scale,
        offset: 0.0,
    }
}

use Dimension as D;
const PI: f64 = std::f64::consts::PI;

/// Units by normalised symbol (see [`normalise`]).
pub(crate) static UNITS: &[Unit] = &[
    u("%", D::Dimensionless, 0.01),
    u("m", D::Length, 1.0),
    u("cm", D::Length, 1e-2),
    u("mm", D::Length, 1e-3),
    u("um", D::Length, 1e-6),
    u("micron", D::Length, 1e-6),
    u("nm", D::Length, 1e-9),
    u("in", D::Length, 0.0254),
    u("m2", D::Area, 1.0),
    u("mm2", D::Area, 1e-6),
    u("kg", D::Mass, 1.0),
    u("g", D::Mass, 1e-3),
    u("s", D::Time, 1.0),
    u("ms", D::Time, 1e-3),
    u("us", D::Time, 1e-6),
    u("min", D::Time, 60.0),
    u("h", D::Time, 3600.0),
    u("N", D::Force, 1.0),
    u("kN", D::Force, 1e3),
    u("MN", D::Force, 1e6),
    u("mN", D::Force, 1e-3),
    u("Nm", D::Moment, 1.0),
    u("Nmm", D::Moment, 1e-3),
    u("kNm", D::Moment, 1e3),
    u("Pa", D::Pressure, 1.0),
    u("kPa", D::Pressure, 1e3),
    u("MPa", D::Pressure, 1e6),
    u("GPa", D::Pressure, 1e9),
    u("bar", D::Pressure, 1e5),
    u("N/mm2", D::Pressure, 1e6),
    u("N/m2", D::Pressure, 1.0),
    // Meyer/Vickers hardness is often printed in kgf/mm² (SPEC F-45).
    u("kgf/mm2", D::Pressure, 9.806_65e6),
    u("rad", D::Angle, 1.0),
    u("mrad", D::Angle, 1e-3),
    u("deg", D::Angle, PI / 180.0),
    u("°", D::Angle, PI / 180.0),
    u("arcmin", D::Angle, PI / 10_800.0),
    u("'", D::Angle, PI / 10_800.0),
    u("arcsec", D::Angle, PI / 648_000.0),
    u("\"", D::Angle, PI / 648_000.0),
    u("rad/s", D::AngularSpeed, 1.0),
    u("rpm", D::AngularSpeed, PI / 30.0),
    u("r/min", D::AngularSpeed, PI / 30.0),
    u("rev/min", D::AngularSpeed, PI / 30.0),
    u("rev/s", D::AngularSpeed, 2.0 * PI),
    u("m/s", D::Speed, 1.0),
    u("mm/s", D::Speed, 1e-3),
    u("km/h", D::Speed, 1.0 / 3.6),
    u("m/s2", D::Acceleration, 1.0),
    u("g0", D::Acceleration, 9.806_65),
    u("K", D::Temperature, 1.0),
    Unit {
        symbol: "C",
        dimension: D::Temperature,
        scale: 1.0,
        offset: 273.15,
    },
    Unit {
        symbol: "°C",
        dimension: D::Temperature,
        scale: 1.0,
        offset: 273.15,
    },
    Unit {
        symbol: "degC",
        dimension: D::Temperature,
        scale: 1.0,
        offset: 273.15,
    },
    u("Pas", D::DynamicViscosity, 1.0),
    u("mPas", D::DynamicViscosity, 1e-3),
    u("cP", D::DynamicViscosity, 1e-3),
    u("P", D::DynamicViscosity, 0.1),
    u("m2/s", D::KinematicViscosity, 1.0),
    u("mm2/s", D::KinematicViscosity, 1e-6),
    u("cSt", D::KinematicViscosity, 1e-6),
    u("St", D::KinematicViscosity, 1e-4),
    u("kg/m3", D::Density, 1.0),
    u("g/cm3", D::Density, 1e3),
    u("N/m", D::Stiffness, 1.0),
    u("N/mm", D::Stiffness, 1e3),
    u("N/um", D::Stiffness, 1e6),
    u("N/m", D::LoadPerLength, 1.0),
    u("kN/m", D::LoadPerLength, 1e3),
    u("N/mm", D::LoadPerLength, 1e3),
    u("kN/mm", D::LoadPerLength, 1e6),
    u("MN/m", D::LoadPerLength, 1e6),
    u("Ns/m", D::Damping, 1.0),
    u("Ns/mm", D::Damping, 1e3),
    u("W", D::Power, 1.0),
    u("kW", D::Power, 1e3),
    u("J", D::Energy, 1.0),
    u("Hz", D::Frequency, 1.0),
    u("W/(mK)", D::ThermalConductivity, 1.0),
    u("W/mK", D::ThermalConductivity, 1.0),
    u("J/(kgK)", D::SpecificHeat, 1.0),
    u("J/kgK", D::SpecificHeat, 1.0),
    u("Nms/rad", D::RotationalDamping, 1.0),
    u("Nms", D::RotationalDamping, 1.0),
    // seed 000 §3.6 prints the cage drag coefficient in N·mm/(rad/ms) = 1e-6 N·m·s/rad.
    u("Nmm/(rad/ms)", D::RotationalDamping, 1e-6),
    u("1/K", D::PerTemperature, 1.0),
    u("1/C", D::PerTemperature, 1.0),
    u("1/Pa", D::PerPressure, 1.0),
    u("1/GPa", D::PerPressure, 1e-9),
    u("1/MPa", D::PerPressure, 1e-6),
    // `7.5e-9/Pa`, `20/GPa`: the number before the slash is the value
    u("/Pa", D::PerPressure, 1.0),
    u("/GPa", D::PerPressure, 1e-9),
    u("/MPa", D::PerPressure, 1e-6),
    u("m2/N", D::PerPressure, 1.0),
    u("1/m2", D::PerArea, 1.0),
    u("1/mm2", D::PerArea, 1e6),
    u("kgm2", D::Inertia, 1.0),
    u("kgmm2", D::Inertia, 1e-6),
    u("gmm2", D::Inertia, 1e-9),
    u("gcm2", D::Inertia, 1e-7),
    // rotating unbalance U (SPEC §3.7: 1032930 "3162.5 g·mm")
    u("kgm", D::Unbalance, 1.0),
    u("kgmm", D::Unbalance, 1e-3),
    u("gmm", D::Unbalance, 1e-6),
    u("gcm", D::Unbalance, 1e-5),
];

/// Normalises a unit spelling: drops white space and the product signs `·`, `*`, `⋅`;
/// micro signs `µ`/`μ` become `u`; superscripts `²`, `³` become `2`, `3`; the prime `′`
/// becomes `'` and `″` becomes `"`; `º` becomes `°`.
pub(crate) fn normalise(symbol: &str) -> String {
    let mut out = String::with_capacity(symbol.len());
    for c in symbol.chars() {
        match c {
            c if c.is_whitespace() => {}
            '·' | '*' | '⋅' => {}
            'µ' | 'μ' => out.push('u'),
            '²' => out.push('2'),
            '³' => out.push('3'),
            '′' => out.push('\''),
            '″' => out.push('"'),
            'º' => out.push('°'),
            _ => out.push(c),
        }
    }
    out
}

/// Looks a unit up, preferring one of the expected dimension when a symbol is shared.
pub(crate) fn lookup(symbol: &str, expected: Dimension) -> Option<&'static Unit> {
    let key = normalise(symbol);
    let mut matches = UNITS.iter().filter(|unit| unit.symbol == key);
    let first = matches.next()?;
    if first.dimension == expected {
        return Some(first);
    }
    matches
        .find(|unit| unit.dimension == expected)
        .or(Some(first))
}

#[cfg(test)]
mod tests {
    use crate::{LoadPerLength, PerPressure, Quantity, Unbalance};

    #[test]
    fn unbalance_units_parse() {
        // SPEC §3.7: 1032930 unbalance 3162.5 g·mm = 3.1625e-3 kg·m
        for text in ["3162.5 g*mm", "3162.5 g·mm", "3162.5 g mm", "316.25 g cm"] {
            let u: Quantity<Unbalance> = text.parse().unwrap();
            assert!((u.si() - 3.1625e-3).abs() < 1e-15, "{text}");
        }
        assert!("3162.5 g".parse::<Quantity<Unbalance>>().is_err());
    }

    /// A line-contact load: the same symbols as a stiffness, its own dimension.
    #[test]
    fn load_per_length_units_parse() {
        for (text, si) in [
            ("250 kN/m", 2.5e5),
            ("0.25 N/mm", 250.0),
            ("1.5 MN/m", 1.5e6),
        ] {
            let w: Quantity<LoadPerLength> = text.parse().unwrap();
            assert!((w.si() - si).abs() < 1e-9 * si, "{text}");
        }
        assert!("2 kN".parse::<Quantity<LoadPerLength>>().is_err());
    }

    /// A pressure–viscosity coefficient α, with or without the `1` before the slash.
    #[test]
    fn per_pressure_units_parse() {
        for text in [
            "7.5e-9/Pa",
            "7.5e-9 1/Pa",
            "7.5 /GPa",
            "7.5 1/GPa",
            "7.5e-3/MPa",
        ] {
            let a: Quantity<PerPressure> = text.parse().unwrap();
            assert!((a.si() - 7.5e-9).abs() < 1e-21, "{text}");
        }
        assert!(
            "7.5e-9".parse::<Quantity<PerPressure>>().is_err(),
            "a text needs its unit"
        );
        assert!("7.5e-9/K".parse::<Quantity<PerPressure>>().is_err());
        assert!("7.5e-9 1/K".parse::<Quantity<PerPressure>>().is_err());
    }
}
