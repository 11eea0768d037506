//! Issue 22 "make it stay fixed": a deterministic mutation test of the model loader. Mutants of
//! the example models (a deleted line, a wrong unit, an extreme number, a truncation, random
//! bytes, a duplicated table) go through model loading, the derived quantities of `rolldyn
//! check` and, for a share of them, a quasi-static skid point. None may panic or produce a
//! non-finite number; each is accepted (exit 0) or rejected as bad input (exit 2). The cargo-fuzz
//! targets in fuzz/ explore further; this is what CI runs.

use rolldyn_geometry::BearingModel;
use rolldyn_quasistatic::{QsError, QuasiStaticOptions, SkidResult};
use rolldyn_setup::quasi_static::{
    LandChoice, QuasiStaticOverrides, cage_land_model, quasi_static_conditions,
};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};

/// Mutants per example model.
const MUTANTS_PER_MODEL: usize = 300;
/// Every this many loadable mutants of a complete bearing are also solved quasi-statically.
const SKID_EVERY: usize = 3;

const EXAMPLES: [&str; 4] = [
    "2002834.toml",
    "1032930.toml",
    "obrien-taylor.toml",
    "contact/32206-straight.toml",
];

const EXTREMES: [&str; 12] = [
    "0",
    "-1",
    "1e308",
    "-1e308",
    "1e-308",
    "5e-324",
    "nan",
    "inf",
    "-inf",
    "1e30",
    "18446744073709551616",
    "-0.0",
];

const UNITS: [&str; 10] = [
    "mm", "kg", "rpm", "N", "C", "GPa", "um", "s", "kg/m3", "rad",
];

/// xorshift64*: a seeded generator, so that every run tests the same mutants.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }

    fn pick<'a>(&mut self, items: &[&'a str]) -> &'a str {
        items[self.below(items.len())]
    }
}

fn examples_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// The line structure of a model: lines kept with their endings.
fn lines(text: &str) -> Vec<String> {
    text.split_inclusive('\n').map(str::to_string).collect()
}

/// A number in `line` replaced by `by` (the first run of digits, sign and exponent).
fn replace_number(line: &str, by: &str) -> Option<String> {
    let start = line.find(|c: char| c.is_ascii_digit())?;
    let end = line[start..]
        .find(|c: char| !(c.is_ascii_digit() || ".eE+-".contains(c)))
        .map_or(line.len(), |e| start + e);
    Some(format!("{}{by}{}", &line[..start], &line[end..]))
}

/// A unit after a number in a quoted value replaced by another unit.
fn replace_unit(line: &str, by: &str) -> Option<String> {
    let open = line.find('"')?;
    let close = open + 1 + line[open + 1..].find('"')?;
    let space = open + line[open..close].rfind(' ')?;
    Some(format!("{}{by}{}", &line[..=space], &line[close..]))
}

/// The table starting at a random `[header]` line, duplicated after itself.
fn duplicate_table(lines: &[String], rng: &mut Rng) -> Option<Vec<String>> {
    let headers: Vec<usize> = (0..lines.len())
        .filter(|&i| lines[i].starts_with('['))
        .collect();
    let start = headers[rng.below(headers.len())];
    let end = (start + 1..lines.len())
        .find(|&i| lines[i].starts_with('['))
        .unwrap_or(lines.len());
    let mut out = lines[..end].to_vec();
    out.extend_from_slice(&lines[start..end]);
    out.extend_from_slice(&lines[end..]);
    Some(out)
}

/// One mutant of `text` and what was done, for the failure message.
fn mutate(text: &str, rng: &mut Rng) -> (String, String) {
    let mut lines = lines(text);
    let i = rng.below(lines.len());
    let kind = rng.below(6);
    let changed = match kind {
        0 => {
            lines.remove(i);
            Some(format!("deleted line {}", i + 1))
        }
        1 => {
            let unit = rng.pick(&UNITS);
            replace_unit(&lines[i], unit).map(|l| {
                lines[i] = l;
                format!("unit of line {} → {unit}", i + 1)
            })
        }
        2 => {
            let number = rng.pick(&EXTREMES);
            replace_number(&lines[i], number).map(|l| {
                lines[i] = l;
                format!("number of line {} → {number}", i + 1)
            })
        }
        3 => {
            let joined = lines.concat();
            let mut at = rng.below(joined.len());
            while !joined.is_char_boundary(at) {
                at -= 1;
            }
            lines = vec![joined[..at].to_string()];
            Some(format!("truncated at byte {at}"))
        }
        4 => {
            let mut bytes = lines.concat().into_bytes();
            let n = 1 + rng.below(8);
            for _ in 0..n {
                let at = rng.below(bytes.len());
                bytes[at] = rng.next() as u8;
            }
            lines = vec![String::from_utf8_lossy(&bytes).into_owned()];
            Some(format!("{n} random bytes"))
        }
        _ => duplicate_table(&lines, rng).map(|l| {
            lines = l;
            "duplicated a table".to_string()
        }),
    };
    let what = changed.unwrap_or_else(|| format!("kind {kind} did not apply to line {}", i + 1));
    (lines.concat(), what)
}

/// The derived quantities `rolldyn check` prints are finite.
fn check_summary(bearing: &BearingModel) -> Result<(), String> {
    let Some(roller) = bearing.roller() else {
        return Ok(());
    };
    let mass = &roller.mass_properties;
    let mut values = vec![
        roller.diameter,
        roller.length,
        roller.profile.effective_length(),
        mass.mass,
        mass.axial_inertia,
        mass.transverse_inertia,
    ];
    values.extend(roller.profile.crown_radius());
    if let BearingModel::Cylindrical(b) = bearing {
        let w = 1000.0 * std::f64::consts::PI / 30.0;
        values.extend([
            b.pitch_diameter(),
            b.geometric_clearance(),
            b.clearance.radial,
            b.epicyclic_cage_speed(w, 0.0),
            b.epicyclic_roller_speed(w, 0.0),
        ]);
        for ring in [&b.inner_ring, &b.outer_ring] {
            let m = &ring.mass_properties;
            values.extend([m.mass, m.axial_inertia, m.transverse_inertia]);
        }
        if let Some(c) = &b.cage {
            let m = &c.mass_properties;
            values.extend([m.mass, m.axial_inertia, m.transverse_inertia]);
            values.extend(c.land_diameter());
        }
    }
    finite("check", &values)
}

fn finite(what: &str, values: &[f64]) -> Result<(), String> {
    match values.iter().position(|v| !v.is_finite()) {
        Some(i) => Err(format!("{what}: value {i} is {}", values[i])),
        None => Ok(()),
    }
}

/// The numbers `rolldyn skid` prints are finite.
fn check_skid(r: &SkidResult) -> Result<(), String> {
    let mut values = vec![
        r.cage_speed_rad_s,
        r.epicyclic_cage_speed_rad_s,
        r.cage_slip,
        r.max_roller_load_n,
        r.operating_clearance_m,
        r.power_loss_w,
        r.power_input_w,
        r.residuals.cage_moment_relative,
        r.residuals.roller_moment_relative,
        r.residuals.force_balance_relative,
    ];
    values.extend(r.min_scuffing_margin);
    for roller in &r.rollers {
        for c in [&roller.inner, &roller.outer] {
            values.extend([
                c.normal_force_n,
                c.max_pressure_pa,
                c.sliding_speed_m_s,
                c.friction_coefficient,
                c.temperature_k,
                c.power_w,
            ]);
        }
    }
    finite("skid", &values)
}

/// What the command line would do with a mutant: 0 (accepted) or 2 (bad input); an `Err` is a
/// broken guarantee (a non-finite number, a numerical failure of an accepted model).
fn run_mutant(text: &str, file: &str, skid: bool) -> Result<u8, String> {
    let Ok(model) = rolldyn_model::parse(text, file) else {
        return Ok(2);
    };
    check_summary(&model.bearing)?;
    let BearingModel::Cylindrical(bearing) = &model.bearing else {
        return Ok(0);
    };
    if !skid {
        return Ok(0);
    }
    let Ok(conditions) = quasi_static_conditions(&model, &QuasiStaticOverrides::default()) else {
        return Ok(2);
    };
    let land = cage_land_model(bearing, LandChoice::Finite);
    let options = QuasiStaticOptions::default();
    match rolldyn_quasistatic::solve_with_land_model(bearing, &conditions, &options, land.as_ref())
    {
        Ok(r) if r.converged => check_skid(&r).map(|()| 0),
        Ok(r) => Err(format!("a result flagged not converged: {:?}", r.residuals)),
        Err(QsError::InvalidInput(_) | QsError::Geometry(_) | QsError::Lubrication(_)) => Ok(2),
        Err(e @ (QsError::NotConverged { .. } | QsError::Contact(_))) => Err(format!(
            "a plausible mutant failed numerically (exit 1): {e}"
        )),
    }
}

#[test]
fn mutants_of_the_examples_never_panic_nor_print_non_finite_numbers() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let mut counts = [0usize; 3];
    let mut skids = 0;
    let mut broken = Vec::new();
    for example in EXAMPLES {
        let path = examples_dir().join(example);
        let text = std::fs::read_to_string(&path).unwrap();
        let file = path.display().to_string();
        let mut loadable = 0;
        for n in 0..MUTANTS_PER_MODEL {
            let (mutant, what) = mutate(&text, &mut rng);
            let loads = rolldyn_model::parse(&mutant, &file).is_ok();
            let skid = loads && loadable % SKID_EVERY == 0;
            loadable += usize::from(loads);
            skids += usize::from(skid);
            let outcome = catch_unwind(AssertUnwindSafe(|| run_mutant(&mutant, &file, skid)));
            match outcome {
                Ok(Ok(code)) => counts[code as usize] += 1,
                Ok(Err(e)) => broken.push(format!("{example} #{n} ({what}): {e}")),
                Err(_) => broken.push(format!("{example} #{n} ({what}): panicked")),
            }
        }
    }
    println!(
        "mutants: {} accepted, {} rejected as bad input; {skids} skid points",
        counts[0], counts[2]
    );
    assert!(broken.is_empty(), "{}", broken.join("\n"));
    assert!(counts.iter().sum::<usize>() >= 1000);
    assert!(counts[0] > 0 && counts[2] > 0, "{counts:?}");
}
