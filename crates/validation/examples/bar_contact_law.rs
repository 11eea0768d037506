//! The roller ↔ cage bar law (pair 34) derived from physics for 2002834 (bar contact at
//! Ø192.5 mm, the seed's FE model) and the O'Brien–Taylor bearing: bar section, compliances,
//! power-law fit, squeeze-film restitution and the matched STEP damping (docs/theory.md
//! §2.3.1, docs/validation/bar-contact-law.md), with the old rolldyn default and the MSC Adams
//! IMPACT defaults as reference rows.
//!
//! `cargo run --release -p rolldyn-validation --example bar_contact_law`

use rolldyn_contact::bar_force::BarFilmSettings;
use rolldyn_contact::cage_bar::{
    BarLawInputs, BarLawKind, DerivationSettings, DerivedBarLaw, Impact, ImpactSettings, PowerLaw,
    critical_damping, derive_for_bearing, film_impact, impact, matching_damping, step_law_impact,
};
use rolldyn_contact::damping::SliceDamping;
use rolldyn_contact::hertz::LineApproachModel;
use rolldyn_dynamics::PairParameters;
use rolldyn_geometry::{BearingModel, CylindricalRollerBearing};
use std::path::Path;

/// Impact speeds of the restitution table (m/s).
const SPEEDS: [f64; 6] = [0.01, 0.02, 0.05, 0.1, 0.2, 0.5];

/// MSC Adams IMPACT defaults ("Contact Parameters for Parts with Small Mass", Adams View help):
/// 1.0E+05 N/mm, exponent 2.2, damping 10 N·s/mm, penetration depth 0.1 mm, for ≈ 1 kg steel.
const ADAMS_K_N_PER_MM: f64 = 1e5;
const ADAMS_EXPONENT: f64 = 2.2;
const ADAMS_DAMPING: f64 = 1e4;
const ADAMS_DEPTH: f64 = 1e-4;
const ADAMS_DEFAULT_MASS: f64 = 1.0;

fn bearing(path: &str) -> Result<(CylindricalRollerBearing, rolldyn_model::Model), String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let model = rolldyn_model::load(&root.join(path)).map_err(|e| e.to_string())?;
    match &model.bearing {
        BearingModel::Cylindrical(b) => Ok((b.clone(), model.clone())),
        _ => Err(format!("{path}: not a cylindrical roller bearing")),
    }
}

/// Adams' small-part rule: the same "5 G" at a penetration of 0.1 % of the part size R (R of
/// the steel sphere of the part's mass, ρ = 8000 kg/m³ as in the help page), `5 M g =
/// K (0.001 R)^2.2` in N and mm; damping at the default's fraction of `2√(K M)`.
fn adams_scaled(mass: f64) -> (PowerLaw, SliceDamping) {
    let r_mm = (3.0 * mass / (4.0 * std::f64::consts::PI * 8000.0)).cbrt() * 1e3;
    let k_mm = 5.0 * mass * 9.81 / (1e-3 * r_mm).powf(ADAMS_EXPONENT);
    let c = ADAMS_DAMPING * (k_mm * mass / (ADAMS_K_N_PER_MM * ADAMS_DEFAULT_MASS)).sqrt();
    (
        PowerLaw {
            k_p: k_mm * 1e3_f64.powf(ADAMS_EXPONENT),
            exponent: ADAMS_EXPONENT,
        },
        SliceDamping::new(c, ADAMS_DEPTH),
    )
}

fn print_case(
    title: &str,
    b: &CylindricalRollerBearing,
    viscosity: f64,
    inner_rpm: f64,
) -> Result<(), String> {
    let settings = DerivationSettings::default();
    let (inputs, law) = derive_for_bearing(b, viscosity, &settings)
        .ok_or("no cage, or windows wider than the bar pitch")?;
    println!("\n## {title}\n");
    print_derivation(&inputs, &law, &settings);
    print_film_table(&inputs, &law);
    let spin = b.epicyclic_roller_speed(inner_rpm * std::f64::consts::PI / 30.0, 0.0);
    println!(
        "\nwith the hydrodynamic lift (roller spin {:.0} rad/s at {inner_rpm} rpm), the library's lubricated law (bar_force, theory (9f)):\n",
        spin.abs()
    );
    let c_h = lift_damping(
        &inputs,
        &law,
        0.5 * spin.abs() * inputs.film.radius,
        &settings,
    )?;
    print_reference_rows(
        inputs.roller_mass,
        law.elastic,
        SliceDamping::new(c_h, law.d),
    );
    Ok(())
}

/// Section, compliances, fit and the damping of the squeeze film without the lift.
fn print_derivation(inputs: &BarLawInputs, law: &DerivedBarLaw, settings: &DerivationSettings) {
    let c = &inputs.compliance;
    let s = c.bar.section;
    println!(
        "bar section: depth {:.2} mm, width {:.2}…{:.2} mm, A = {:.1} mm², I = {:.0} mm⁴; span {:.2} mm, loads F/2 at {:.3} mm from each clamp",
        s.depth * 1e3,
        s.width_inner * 1e3,
        s.width_outer * 1e3,
        s.area * 1e6,
        s.second_moment * 1e12,
        c.bar.span * 1e3,
        c.bar.offset * 1e3
    );
    println!(
        "line contact: R_w {:.2} mm on a flat, length {:.2} mm, E' {:.1} GPa; roller mass {:.2} g; oil η {:.2} mPa·s; d = h(Λ=1) {:.2} µm\n",
        c.contact.reduced_radius * 1e3,
        c.contact.length * 1e3,
        c.contact.reduced_modulus * 1e-9,
        inputs.roller_mass * 1e3,
        inputs.film.viscosity * 1e3,
        inputs.contact_film * 1e6
    );
    println!("| F (N) | bending (m/N) | shear (m/N) | contact δ/F (m/N) | total δ (µm) |");
    println!("|---|---|---|---|---|");
    for f in [10.0, 100.0] {
        let contact = c.contact.approach(f, LineApproachModel::PalmgrenScaled) / f;
        println!(
            "| {f:.0} | {:.3e} | {:.3e} | {:.3e} | {:.3} |",
            c.bar.bending_compliance(),
            c.bar.shear_compliance(),
            contact,
            c.approach(f) * 1e6
        );
    }
    let mid = {
        let mut bar = c.bar;
        bar.offset = 0.5 * bar.span;
        bar.bending_compliance() + bar.shear_compliance()
    };
    println!("\n(one load at mid-span instead: bar compliance {mid:.3e} m/N)\n");
    println!(
        "fit over {:.0}…{:.0} N: K_p = {:.4e} N/m^n, n = {:.4}, largest force error {:.2} %",
        settings.force_range.0,
        settings.force_range.1,
        law.elastic.k_p,
        law.elastic.exponent,
        100.0 * law.fit_error
    );
    let rule = if law.critically_capped {
        "the film alone restitutes less than any STEP law can: critical damping at the impact penetration"
    } else {
        "the STEP law restitutes like the film"
    };
    println!(
        "squeeze film without the lift: C_h = {:.4} N·s/m at d = {:.2} µm (film restitution {:.3} at {} m/s; {rule})\n",
        law.c_h,
        law.d * 1e6,
        law.restitution,
        settings.reference_speed
    );
}

/// Restitution and peak force through the squeeze film and with the STEP law, per speed.
fn print_film_table(inputs: &BarLawInputs, law: &DerivedBarLaw) {
    let imp = ImpactSettings::default();
    let m = inputs.roller_mass;
    let derived = SliceDamping::new(law.c_h, law.d);
    println!(
        "| impact speed (m/s) | film: e | film: peak F (N) | STEP law: e | STEP law: peak F (N) |"
    );
    println!("|---|---|---|---|---|");
    for v in SPEEDS {
        let film = film_impact(m, v, law.elastic, inputs.film, law.d, imp);
        let step = step_law_impact(m, v, law.elastic, derived, imp);
        println!(
            "| {v} | {:.3} | {:.2} | {:.3} | {:.1} |",
            film.restitution, film.peak_force, step.restitution, step.peak_force
        );
    }
}

/// The lubricated law per speed; returns the chosen C_h: matched to the film with the lift
/// where it turns the roller above d at the reference speed, else the squeeze-film value.
fn lift_damping(
    inputs: &BarLawInputs,
    law: &DerivedBarLaw,
    entrainment_speed: f64,
    settings: &DerivationSettings,
) -> Result<f64, String> {
    println!(
        "| impact speed (m/s) | e | thinnest film (µm; < 0: elastic approach) | peak force (N) |"
    );
    println!("|---|---|---|---|");
    for v in SPEEDS {
        let (e, h_min, peak) = lift_impact(inputs, law, entrainment_speed, v);
        let note = if h_min < law.d {
            " (asperities meet)"
        } else {
            ""
        };
        println!("| {v} | {e:.3} | {:.2}{note} | {peak:.1} |", h_min * 1e6);
    }
    let (m, v_ref) = (inputs.roller_mass, settings.reference_speed);
    let (e_lift, h_min, _) = lift_impact(inputs, law, entrainment_speed, v_ref);
    if h_min < law.d {
        println!(
            "\nchosen: the asperities meet at {v_ref} m/s even with the lift: C_h = {:.0} N·s/m (squeeze film and contact) at d = {:.2} µm",
            law.c_h,
            law.d * 1e6
        );
        return Ok(law.c_h);
    }
    let c_h = matching_damping(m, v_ref, law.elastic, law.d, e_lift, settings.impact)
        .min(critical_damping(m, v_ref, law.elastic, law.d));
    println!(
        "\nchosen: with the lift the film alone turns the roller at {v_ref} m/s (e = {e_lift:.3}): C_h = {c_h:.0} N·s/m at d = {:.2} µm restitutes alike",
        law.d * 1e6
    );
    Ok(c_h)
}

/// Restitution and peak force at 0.1 m/s of the old default, the chosen law and Adams' rows.
fn print_reference_rows(mass: f64, elastic: PowerLaw, chosen: SliceDamping) {
    let old = PairParameters::roller_cage_default();
    let adams = (
        PowerLaw {
            k_p: ADAMS_K_N_PER_MM * 1e3_f64.powf(ADAMS_EXPONENT),
            exponent: ADAMS_EXPONENT,
        },
        SliceDamping::new(ADAMS_DAMPING, ADAMS_DEPTH),
    );
    let rows: [(&str, (PowerLaw, SliceDamping)); 4] = [
        (
            "old rolldyn default",
            (
                PowerLaw {
                    k_p: old.k_p,
                    exponent: old.exponent,
                },
                SliceDamping::new(old.c_h, old.d),
            ),
        ),
        ("derived law (chosen C_h)", (elastic, chosen)),
        ("Adams IMPACT default (1 kg part)", adams),
        ("Adams scaled to the roller mass", adams_scaled(mass)),
    ];
    println!(
        "\n| law | K_p (N/m^n) | n | C_h (N·s/m) | d (µm) | e at 0.1 m/s | peak F at 0.1 m/s (N) |"
    );
    println!("|---|---|---|---|---|---|---|");
    for (name, (elastic, damping)) in rows {
        let Impact {
            restitution,
            peak_force,
            ..
        } = step_law_impact(mass, 0.1, elastic, damping, ImpactSettings::default());
        println!(
            "| {name} | {:.3e} | {:.2} | {:.1} | {:.2} | {restitution:.3} | {peak_force:.1} |",
            elastic.k_p,
            elastic.exponent,
            damping.c_max,
            damping.delta_star * 1e6
        );
    }
}

/// A roller striking the bar through the library's lubricated law (squeeze and wedge film,
/// then the elastic law; theory (9f)) at `speed` from a 50 µm gap, RK4 until it is back there.
/// Returns the restitution, the thinnest gap (m, negative = elastic approach) and the largest
/// force (N).
fn lift_impact(
    inputs: &BarLawInputs,
    law: &DerivedBarLaw,
    entrainment_speed: f64,
    speed: f64,
) -> (f64, f64, f64) {
    let lubricated = law.force_law(inputs, BarLawKind::Lubricated, &BarFilmSettings::default());
    let (h0, length) = (50e-6, inputs.film.length);
    let film_damping = inputs.film.damping(inputs.contact_film);
    let i = impact(
        inputs.roller_mass,
        speed,
        law.elastic,
        film_damping,
        |d, v| lubricated.normal_force(h0 - d, -v, entrainment_speed, length),
        ImpactSettings::default(),
    );
    (i.restitution, h0 - i.max_penetration, i.peak_force)
}

fn run() -> Result<(), String> {
    let (b2002834, model) = bearing("examples/2002834.toml")?;
    for celsius in [100.0, 50.0] {
        print_case(
            &format!("2002834, VNII NP 50-1-4u at {celsius} °C"),
            &b2002834,
            viscosity(&model, celsius)?,
            8163.0,
        )?;
    }
    let (bot, model) = bearing("examples/obrien-taylor.toml")?;
    print_case(
        "O'Brien–Taylor, NVI 65 at 54.5 °C",
        &bot,
        viscosity(&model, 54.5)?,
        4000.0,
    )
}

/// Dynamic viscosity (Pa·s) of the model's oil at `celsius`.
fn viscosity(model: &rolldyn_model::Model, celsius: f64) -> Result<f64, String> {
    let oil = &model
        .lubrication
        .as_ref()
        .ok_or("the model has no [lubricant]")?
        .oil;
    oil.dynamic_viscosity(oil.clamp_temperature(celsius + 273.15))
        .map_err(|e| e.to_string())
}

fn main() {
    if let Err(e) = run() {
        eprintln!("bar_contact_law: {e}");
        std::process::exit(1);
    }
}
