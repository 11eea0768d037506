//! Oil selection shared by `oils`, `traction` and `film`: a built-in name or a user TOML file,
//! and the temperature-range policy (warn, or error with `--strict`).

use crate::failure::Failure;
use rolldyn_lubrication::{Lubricant, lubricant_by_name};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct OilArgs {
    /// Built-in oil (see `rolldyn oils`), e.g. `pao1-vg320`.
    #[arg(long, default_value = "pao1-vg320")]
    pub oil: String,
    /// User oil file (TOML with the keys of the built-in library; see docs/lubricants.md).
    #[arg(long, conflicts_with = "oil")]
    pub oil_file: Option<PathBuf>,
    /// Treat a temperature outside the oil's documented range as an error instead of a warning.
    #[arg(long)]
    pub strict: bool,
}

impl OilArgs {
    /// The selected lubricant.
    pub fn load(&self) -> Result<Lubricant, Failure> {
        let Some(path) = &self.oil_file else {
            return lubricant_by_name(&self.oil).map_err(|e| Failure::Input(e.to_string()));
        };
        let file = path.display().to_string();
        let text = rolldyn_model::read_input_file(path)
            .map_err(|e| Failure::Input(format!("{file}: {e}")))?;
        toml::from_str(&text).map_err(|e| {
            let line = e
                .span()
                .map(|s| {
                    format!(
                        ":{}",
                        text[..s.start.min(text.len())].matches('\n').count() + 1
                    )
                })
                .unwrap_or_default();
            Failure::Input(format!(
                "{file}{line}: {}",
                e.message().trim().replace('\n', " ")
            ))
        })
    }

    /// Warns (or fails with `--strict`) when `temperature_k` is outside the oil's range.
    pub fn check_temperature(&self, oil: &Lubricant, temperature_k: f64) -> Result<(), Failure> {
        if oil.in_range(temperature_k) {
            return Ok(());
        }
        let [lo, hi] = oil.temperature_range_k;
        let message = format!(
            "{:.1} °C is outside the documented range of {} ({:.0}…{:.0} °C); properties are clamped to the range",
            temperature_k - 273.15,
            oil.name,
            lo - 273.15,
            hi - 273.15
        );
        if self.strict {
            return Err(Failure::Input(
                message.replace("; properties are clamped to the range", ""),
            ));
        }
        eprintln!("rolldyn: warning: {message}");
        Ok(())
    }
}
