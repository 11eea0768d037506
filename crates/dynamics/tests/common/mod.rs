//! Shared helpers of the integration tests.
#![allow(dead_code)]

use rolldyn_dynamics::*;
use rolldyn_geometry::CylindricalRollerBearing;
use rolldyn_lubrication::{TractionModel, lubricant_by_name};

pub fn bearing(name: &str) -> CylindricalRollerBearing {
    let path = format!("{}/../../examples/{name}.toml", env!("CARGO_MANIFEST_DIR"));
    match rolldyn_model::load(std::path::Path::new(&path))
        .expect("example model")
        .bearing
    {
        rolldyn_model::BearingModel::Cylindrical(b) => b,
        _ => panic!("not a bearing"),
    }
}

/// 2002834 with fewer slices (tests).
pub fn b2002834(slices: usize) -> CylindricalRollerBearing {
    let mut b = bearing("2002834");
    b.roller.slice_count = slices;
    b
}

pub fn pao() -> TractionModel {
    TractionModel::muraki(lubricant_by_name("pao1-vg320").unwrap()).unwrap()
}

pub fn rpm(n: f64) -> f64 {
    n * std::f64::consts::TAU / 60.0
}

/// Records a few quantities of every sample.
#[derive(Default)]
pub struct Recorder {
    pub samples: usize,
    pub revolutions: Vec<RevolutionSummary>,
    pub last_inner_forces: Vec<f64>,
    pub cage_speed: Vec<f64>,
}

impl OutputSink for Recorder {
    fn sample(&mut self, _t: f64, s: &Snapshot) {
        self.samples += 1;
        self.last_inner_forces = s.rollers.inner.force_n.to_vec();
        self.cage_speed.push(s.cage_speed_rad_s);
    }
    fn revolution(&mut self, r: &RevolutionSummary) {
        self.revolutions.push(*r);
    }
}
