//! Oil selection shared by `oils`, `traction` and `film`: a built-in name or a user TOML file,
//! and the temperature-range policy (warn, or error with `--strict`).

use rolldyn::oil::OilChoice;
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
    /// The oil chosen.
    pub fn choice(&self) -> OilChoice {
        OilChoice {
            oil: self.oil.clone(),
            oil_file: self.oil_file.clone(),
            strict: self.strict,
        }
    }
}
