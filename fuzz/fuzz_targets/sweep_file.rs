//! Sweep files: `SweepFile::load` reads its input from a path, so each input is written to a
//! temporary file next to a copy of the default model it may name as `model = "m.toml"`.
#![no_main]

use std::path::PathBuf;
use std::sync::OnceLock;

fn dir() -> &'static PathBuf {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let dir = std::env::temp_dir().join(format!("rolldyn-fuzz-sweep-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temporary folder");
        std::fs::write(dir.join("m.toml"), rolldyn_model::DEFAULT_MODEL).expect("model copy");
        dir
    })
}

libfuzzer_sys::fuzz_target!(|bytes: &[u8]| {
    let path = dir().join("sweep.toml");
    std::fs::write(&path, bytes).expect("sweep input");
    let _ = rolldyn_sweep::SweepFile::load(&path);
});
