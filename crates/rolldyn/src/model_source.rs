//! Where an analysis' bearing model comes from: a model file, the embedded default model
//! (bearing 2002834), or a model built in memory (a Python `Model` with overrides).

use crate::failure::Failure;
use std::path::{Path, PathBuf};

/// The name an answer gives the embedded default model.
pub const EMBEDDED_MODEL_NAME: &str = "<embedded 2002834.toml>";

/// A bearing model to analyse.
#[derive(Clone, Debug, Default)]
pub enum ModelSource {
    /// The embedded default model, bearing 2002834 (`rolldyn_model::DEFAULT_MODEL`).
    #[default]
    Embedded,
    /// A model file (docs/model-format.md).
    File(PathBuf),
    /// A model already parsed: `source` names it (its file, or the embedded model), `text` is
    /// its TOML with any overrides applied.
    Given {
        source: String,
        text: String,
        model: Box<rolldyn_model::Model>,
    },
}

impl ModelSource {
    /// A model file, or the embedded model when `path` is `None`.
    pub fn file_or_embedded(path: Option<&Path>) -> Self {
        path.map_or(Self::Embedded, |p| Self::File(p.to_path_buf()))
    }

    /// Reads and parses a model file (or the embedded model) into a [`ModelSource::Given`].
    pub fn read(path: Option<&Path>) -> Result<Self, Failure> {
        let (source, text) = match path {
            Some(path) => (
                path.display().to_string(),
                rolldyn_model::read_input_file(path)
                    .map_err(|reason| Failure::Input(format!("{}: {reason}", path.display())))?,
            ),
            None => (
                EMBEDDED_MODEL_NAME.to_string(),
                rolldyn_model::DEFAULT_MODEL.to_string(),
            ),
        };
        let model = rolldyn_model::parse(&text, &source)?;
        Ok(Self::Given {
            source,
            text,
            model: Box::new(model),
        })
    }

    /// The model parsed.
    pub fn load(&self) -> Result<rolldyn_model::Model, Failure> {
        Ok(match self {
            Self::Embedded => {
                rolldyn_model::parse(rolldyn_model::DEFAULT_MODEL, EMBEDDED_MODEL_NAME)?
            }
            Self::File(path) => rolldyn_model::load(path)?,
            Self::Given { model, .. } => (**model).clone(),
        })
    }

    /// The model file, when the model is a file's (given in memory or not).
    pub fn file(&self) -> Option<&Path> {
        match self {
            Self::File(path) => Some(path),
            Self::Given { source, .. } if source != EMBEDDED_MODEL_NAME => Some(Path::new(source)),
            _ => None,
        }
    }

    /// The model's TOML text as analysed (a file's text is read again).
    pub fn text(&self) -> Option<String> {
        match self {
            Self::Embedded => Some(rolldyn_model::DEFAULT_MODEL.to_string()),
            Self::File(path) => std::fs::read_to_string(path).ok(),
            Self::Given { text, .. } => Some(text.clone()),
        }
    }
}
