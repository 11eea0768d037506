//! Material inputs: the fuzz input as the body of the default model's cage material table
//! (`[materials.NAME]`: `sn_curve`, `ultimate_strength`, `fatigue_like`, elastic data) must
//! load or be refused, never panic; a cage material that loads resolves its S–N curve or says
//! why not.
#![no_main]

libfuzzer_sys::fuzz_target!(|text: &str| {
    let model = format!(
        "{}\n[materials.fuzzed]\n{text}\n",
        rolldyn_model::DEFAULT_MODEL.replacen("material = \"cage-steel\"", "material = \"fuzzed\"", 1)
    );
    let Ok(model) = rolldyn_model::parse(&model, "fuzz.toml") else {
        return;
    };
    if let Ok(bearing) = model.bearing.require_cylindrical("fuzz") {
        let material = rolldyn_fatigue::cage_material::CageMaterial::of(bearing);
        let _ = rolldyn_fatigue::cage_material::resolve(
            material.as_ref(),
            &Default::default(),
            rolldyn_fatigue::mean_stress::MeanStressCorrection::Goodman,
        );
    }
});
