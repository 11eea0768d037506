//! Demo: the most complete analysis available, on the embedded default model (bearing 2002834,
//! SPEC §1.6 a / F-02): geometry check, quasi-static skidding at the model's operating point, a
//! short 6-DOF dynamics run, and the inner-raceway contact of the most loaded roller by Hertz,
//! slices and the Boussinesq solver at 0′/4′/8′ tilt.

use crate::analysis::{Analysis, Context};
use crate::check::{Summary, summarise};
use crate::contact::{ContactResult, LawName, Method, solve, to_json};
use crate::failure::Failure;
use crate::model_source::ModelSource;
use crate::simulate::{step_limits, summary_json, summary_text};
use crate::table::Tables;
use rolldyn_contact::roller_raceway::RollerRacewayContact;
use rolldyn_dynamics::output::NullSink;
use rolldyn_geometry::BearingModel;
use rolldyn_quasistatic::{QuasiStaticOptions, SkidResult};
use rolldyn_setup::quasi_static::{
    LandChoice, QuasiStaticOverrides, cage_land_model, quasi_static_conditions,
};
use rolldyn_units::ARCMIN;
use serde::{Deserialize, Serialize};
use std::fmt;

const TILTS_ARCMIN: [f64; 3] = [0.0, 4.0, 8.0];

/// How long the demo's dynamics run.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct DemoRequest {
    /// Cage revolutions of the dynamics run (at least 0.1).
    pub revolutions: f64,
}

impl Default for DemoRequest {
    fn default() -> Self {
        Self { revolutions: 2.0 }
    }
}

/// The demo's four analyses.
#[derive(Clone, Debug, Serialize)]
pub struct DemoResult {
    pub model: Summary,
    pub quasi_static: SkidResult,
    pub dynamics: serde_json::Value,
    pub inner_raceway_contact: Vec<ContactResult>,
    /// The four parts as the command line prints them.
    #[serde(skip)]
    text: String,
}

impl Tables for DemoResult {}

impl fmt::Display for DemoResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

/// The demo analysis, always on the embedded model.
pub struct Demo;

impl Analysis for Demo {
    const NAME: &'static str = "demo";
    type Request = DemoRequest;
    type Result = DemoResult;

    fn run(request: &DemoRequest, _context: &Context<'_>) -> Result<DemoResult, Failure> {
        let model = ModelSource::Embedded.load()?;
        let BearingModel::Cylindrical(bearing) = &model.bearing else {
            return Err(Failure::Run(
                "the embedded model is a cylindrical bearing".into(),
            ));
        };
        let op = &model.operating;
        let missing = |what: &str| Failure::Run(format!("the embedded model lacks {what}"));
        let speed = op
            .inner_speed
            .ok_or_else(|| missing("operating.inner_speed"))?;
        let load = op
            .radial_load
            .ok_or_else(|| missing("operating.radial_load"))?;
        let oil_t = op
            .temperatures
            .oil
            .ok_or_else(|| missing("operating.temperatures.oil"))?;
        let summary = summarise(&model.bearing, speed, 0.0);
        let mut text = vec![summary.to_string()];

        let qs_conditions = quasi_static_conditions(&model, &QuasiStaticOverrides::default())?;
        let skid = rolldyn_quasistatic::solve_with_land_model(
            bearing,
            &qs_conditions,
            &QuasiStaticOptions::default(),
            cage_land_model(bearing, LandChoice::Finite).as_ref(),
        )
        .map_err(|e| Failure::Run(format!("quasi-static model: {e}")))?;
        text.push(format!(
            "\nQuasi-static skidding at {:.0} rpm, {:.0} N, oil {:.0} °C:",
            speed * 30.0 / std::f64::consts::PI,
            load,
            oil_t - 273.15
        ));
        text.push(format!(
            "  cage slip {:.6}, max roller load {:.1} N, operating clearance {:.4} mm, friction power {:.1} W",
            skid.cage_slip,
            skid.max_roller_load_n,
            skid.operating_clearance_m * 1e3,
            skid.power_loss_w
        ));

        let (mut sim, revolution) =
            rolldyn_setup::prepare(&model, &rolldyn_setup::Overrides::default(), 0.0, None)?;
        let revolution = revolution.ok_or_else(|| missing("a running inner ring"))?;
        let t_end = request.revolutions.max(0.1) * revolution;
        let dynamics = sim
            .run_until(t_end, &mut NullSink, &mut |_| {})
            .map_err(|e| Failure::Run(format!("dynamics: {e}")))?;
        text.push(format!(
            "\nDynamics, {} cage revolutions from the default start:",
            request.revolutions
        ));
        let limits = step_limits(&sim.step_limits());
        text.push(summary_text(model.bearing.name(), &dynamics, &limits));

        let roller_load = skid.max_roller_load_n.max(1.0);
        text.push(format!(
            "\nInner-raceway contact of the most loaded roller ({roller_load:.0} N), Boussinesq grid of the Hertz contact width:"
        ));
        text.push(format!(
            "  {:>6} {:>10} {:>12} {:>10} {:>10} {:>8} {:>8}",
            "tilt ′", "method", "approach µm", "p_max MPa", "p_mid MPa", "K", "ms"
        ));
        let mut contacts = Vec::new();
        for tilt in TILTS_ARCMIN {
            let contact = RollerRacewayContact::from_model(&model.bearing, true, tilt * ARCMIN)
                .map_err(|e| Failure::Run(e.to_string()))?;
            for method in [Method::Hertz, Method::Slices, Method::Boussinesq] {
                let r = solve(&contact, method, roller_load, None, None, LawName::Seed)?;
                text.push(format!(
                    "  {:>6.0} {:>10} {:>12.3} {:>10.0} {:>10.0} {:>8.3} {:>8.2}",
                    tilt,
                    r.method.name(),
                    r.approach_m * 1e6,
                    r.max_pressure_pa * 1e-6,
                    r.mid_pressure_pa * 1e-6,
                    r.concentration_factor,
                    r.solve_time_s * 1e3
                ));
                contacts.push(to_json(model.bearing.name(), &r));
            }
        }
        Ok(DemoResult {
            model: summary,
            quasi_static: skid,
            dynamics: summary_json(model.bearing.name(), &dynamics),
            inner_raceway_contact: contacts,
            text: text.join("\n"),
        })
    }
}
