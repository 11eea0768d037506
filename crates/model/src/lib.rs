//! Bearing model files (TOML) for rolldyn: schema, unit conversion at the boundary and
//! validation with errors that name the file, line, key and reason.
//!
//! ```
//! let model = rolldyn_model::parse(rolldyn_model::DEFAULT_MODEL, "2002834.toml").unwrap();
//! assert_eq!(model.bearing.name(), "2002834");
//! ```

pub mod bounds;
mod convert;
mod dynamics;
mod error;
pub mod journal;
pub mod oil_file;
mod operation;
mod raceway_wear;
pub mod schema;
pub mod tapered;

pub use convert::DEFAULT_SLICES;
pub use dynamics::{
    CageLandLaw, DynamicsInputs, EndFrictionLaw, EndPairInputs, PairInputs, RollerCageLaw,
};
pub use error::{
    LocatedToml, MAX_QUOTED_CHARS, ModelError, Segment as KeySegment, shorten_long_words,
};
pub use oil_file::{load_oil_file, parse_oil_file};
pub use operation::{
    DEFAULT_STARTUP_REVOLUTIONS, FixedLoad, FrozenPoint, Lubrication, Operating, Schedules,
    Startup, Temperatures,
};
pub use raceway_wear::{RACEWAY_WEAR_HEADER, read_raceway_wear_csv, write_raceway_wear_csv};
pub use rolldyn_geometry::BearingModel;

/// Everything a model file describes.
#[derive(Debug, Clone, PartialEq)]
pub struct Model {
    pub bearing: BearingModel,
    /// `[lubricant]`, if given.
    pub lubrication: Option<Lubrication>,
    /// `[operating]` (every value optional).
    pub operating: Operating,
    /// `[[operating.loads]]` and the time schedules of `[operating]` (SPEC §3.7).
    pub schedules: Schedules,
    /// `[startup]`: frozen points of a start-up (seed 000 §3.1.2), if given.
    pub startup: Option<Startup>,
    /// `[dynamics]`: contact parameters (SPEC Table 2.1) and cage drag; defaults where silent.
    pub dynamics: DynamicsInputs,
    /// The file the model was read from, to name it in errors found after loading.
    pub source: Source,
}

/// The name and text of a model file: errors found after loading (a missing oil property, an
/// override out of bounds) name the file, line and key like load-time errors.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Source {
    pub file: String,
    text: String,
}

impl Source {
    /// The model file `file` whose text is `text`.
    pub fn new(file: impl Into<String>, text: impl Into<String>) -> Self {
        Self {
            file: file.into(),
            text: text.into(),
        }
    }

    /// The text of the model file.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// The error `reason` at dotted `key` of this file (at its line when the key is in it).
    pub fn error(&self, key: &str, reason: impl Into<String>) -> ModelError {
        let tree = DeTable::parse(&self.text).ok();
        let span = tree.as_ref().and_then(|t| error::span_of(t, key));
        located(&self.text, &self.file, key, span, reason.into())
    }
}

use std::path::Path;
use toml::de::DeTable;

/// The embedded default model: cylindrical roller bearing 2002834 (SPEC §1.6 a, F-02).
pub const DEFAULT_MODEL: &str = include_str!("../../../examples/2002834.toml");

/// The bearing of the embedded default model (2002834), for examples, benches and tests.
pub fn default_cylindrical_bearing() -> rolldyn_geometry::CylindricalRollerBearing {
    match parse(DEFAULT_MODEL, "2002834.toml")
        .expect("the embedded model is valid (tests/examples.rs)")
        .bearing
    {
        BearingModel::Cylindrical(b) => b,
        _ => unreachable!("2002834 is a cylindrical roller bearing"),
    }
}

/// Reads and validates a model file.
pub fn load(path: &Path) -> Result<Model, ModelError> {
    let (text, file) = read(path)?;
    parse(&text, &file)
}

/// The text of the file at `path` and its name for errors.
fn read(path: &Path) -> Result<(String, String), ModelError> {
    let file = path.display().to_string();
    match read_input_file(path) {
        Ok(text) => Ok((text, file)),
        Err(reason) => Err(ModelError {
            file,
            position: None,
            key: String::new(),
            reason,
        }),
    }
}

/// Largest input file rolldyn reads (model, sweep, journal and oil files), bytes.
pub const MAX_INPUT_FILE_BYTES: u64 = 8 << 20;

/// The UTF-8 text of an input file of at most [`MAX_INPUT_FILE_BYTES`]; the error says why
/// not (without the path, which the caller names).
pub fn read_input_file(path: &Path) -> Result<String, String> {
    use std::io::Read;
    let cannot = |e: std::io::Error| format!("cannot read the file: {e}");
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .map_err(cannot)?
        .take(MAX_INPUT_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(cannot)?;
    if bytes.len() as u64 > MAX_INPUT_FILE_BYTES {
        return Err(format!(
            "the file is larger than {} MiB: not a rolldyn input file",
            MAX_INPUT_FILE_BYTES >> 20
        ));
    }
    String::from_utf8(bytes).map_err(|e| {
        format!(
            "not UTF-8 text (invalid byte at offset {})",
            e.utf8_error().valid_up_to()
        )
    })
}

/// A TOML document deserialised into a schema `T`, kept with its spans so that later checks
/// can name the line of a key: the one error locator of the project's TOML files.
struct Document<'a, T> {
    schema: T,
    text: &'a str,
    file: &'a str,
    tree: toml::Spanned<DeTable<'a>>,
}

impl<'a, T: serde::de::DeserializeOwned> Document<'a, T> {
    /// Parses `text` (named `file` in errors) into `T`.
    fn parse(text: &'a str, file: &'a str) -> Result<Self, ModelError> {
        let error = |key: &str, span: Option<std::ops::Range<usize>>, reason| {
            located(text, file, key, span, reason)
        };
        let tree = LocatedToml::parse(text, file)?.tree;
        let deserializer = toml::de::Deserializer::from(tree.clone());
        let schema = serde_path_to_error::deserialize(deserializer).map_err(|e| {
            let key = path_key(e.path());
            let span = error::span_of(&tree, &key).or_else(|| e.inner().span());
            error(&key, span, serde_message(e.inner()))
        })?;
        Ok(Self {
            schema,
            text,
            file,
            tree,
        })
    }

    /// The error `reason` at dotted `key` (at its line when the key is in the file).
    fn error(&self, key: &str, reason: String) -> ModelError {
        located(
            self.text,
            self.file,
            key,
            error::span_of(&self.tree, key),
            reason,
        )
    }
}

fn located(
    text: &str,
    file: &str,
    key: &str,
    span: Option<std::ops::Range<usize>>,
    reason: String,
) -> ModelError {
    ModelError {
        file: file.to_string(),
        position: span.map(|s| error::line_column(text, s.start)),
        key: key.to_string(),
        reason,
    }
}

/// Parses and validates model text; `file` names it in errors.
pub fn parse(text: &str, file: &str) -> Result<Model, ModelError> {
    if declared_kind(text) == Some(schema::ModelKind::DoubleRowTapered) {
        return parse_tapered(text, file);
    }
    let document = Document::<schema::ModelFile>::parse(text, file)?;
    let schema = &document.schema;
    let locate = |e: rolldyn_geometry::GeometryError| document.error(&e.key, e.reason);
    let mut bearing = convert::build(schema).map_err(locate)?;
    raceway_wear::attach(&mut bearing, schema, file).map_err(locate)?;
    bearing.validate().map_err(locate)?;
    let sections = SharedSections {
        lubricant: schema.lubricant.as_ref(),
        operating: schema.operating.as_ref(),
        startup: schema.startup.as_ref(),
        dynamics: schema.dynamics.as_ref(),
    };
    complete(bearing, sections, text, file).map_err(locate)
}

/// A double-row tapered bearing model (its own tables, docs/model-format.md).
fn parse_tapered(text: &str, file: &str) -> Result<Model, ModelError> {
    let document = Document::<tapered::TaperedModelFile>::parse(text, file)?;
    let schema = &document.schema;
    let locate = |e: rolldyn_geometry::GeometryError| document.error(&e.key, e.reason);
    tapered::refuse_unread_keys(schema).map_err(locate)?;
    let bearing = BearingModel::Tapered(tapered::build(schema).map_err(locate)?);
    bearing.validate().map_err(locate)?;
    let sections = SharedSections {
        lubricant: schema.lubricant.as_ref(),
        operating: schema.operating.as_ref(),
        startup: None,
        dynamics: schema.dynamics.as_ref(),
    };
    complete(bearing, sections, text, file).map_err(locate)
}

/// `[bearing] kind` of a model text, if it can be read (errors are reported by the full parse).
fn declared_kind(text: &str) -> Option<schema::ModelKind> {
    #[derive(serde::Deserialize)]
    struct Probe {
        bearing: ProbeBearing,
    }
    #[derive(serde::Deserialize)]
    struct ProbeBearing {
        kind: schema::ModelKind,
    }
    toml::from_str::<Probe>(text).ok().map(|p| p.bearing.kind)
}

/// The tables every kind of model shares.
struct SharedSections<'a> {
    lubricant: Option<&'a schema::LubricantSection>,
    operating: Option<&'a schema::OperatingSection>,
    startup: Option<&'a schema::StartupSection>,
    dynamics: Option<&'a schema::DynamicsSection>,
}

/// The model of a validated bearing and the shared tables.
fn complete(
    bearing: BearingModel,
    sections: SharedSections,
    text: &str,
    file: &str,
) -> Result<Model, rolldyn_geometry::GeometryError> {
    let schedules = operation::schedules(sections.operating)?;
    if let (Some(points), BearingModel::Cylindrical(b)) = (&schedules.clearance, &bearing) {
        // the interference limit of `clearance.radial` (0.2 % of D_w) applies at every time
        let limit = -0.002 * b.roller.diameter;
        if let Some(&(t, g)) = points.iter().find(|p| p.1 < limit) {
            return Err(rolldyn_geometry::GeometryError::new(
                "operating.clearance_schedule.radial",
                format!(
                    "preload {:.4} mm at {t} s exceeds 0.2 % of the roller diameter: an interference, not a preload",
                    -g * 1e3
                ),
            ));
        }
    }
    let operating = operation::operating(sections.operating)?;
    check_speeds(&bearing, &operating, &schedules)?;
    Ok(Model {
        bearing,
        lubrication: operation::lubrication(sections.lubricant, file)?,
        operating,
        schedules,
        startup: operation::startup(sections.startup)?,
        dynamics: dynamics::dynamics(sections.dynamics)?,
        source: Source {
            file: file.to_string(),
            text: text.to_string(),
        },
    })
}

/// The speeds of `[operating]` and its speed schedule within [`bounds::check_speed`], its
/// radial loads within [`bounds::check_radial_load`].
fn check_speeds(
    bearing: &BearingModel,
    operating: &Operating,
    schedules: &Schedules,
) -> Result<(), rolldyn_geometry::GeometryError> {
    let given = [
        ("operating.inner_speed", operating.inner_speed),
        ("operating.outer_speed", operating.outer_speed),
    ];
    let scheduled = schedules
        .speed
        .iter()
        .flatten()
        .map(|&(_, w)| ("operating.speed_schedule.speed", Some(w)));
    for (key, speed) in given.into_iter().chain(scheduled) {
        if let Some(w) = speed {
            bounds::check_speed(bearing, key, w)?;
        }
    }
    if let Some(load) = operating.radial_load {
        bounds::check_radial_load(bearing, "operating.radial_load", load)?;
    }
    for (i, load) in schedules.loads.iter().enumerate() {
        bounds::check_radial_load(
            bearing,
            &format!("operating.loads[{i}].magnitude"),
            load.magnitude,
        )?;
        if let Some((after, _)) = load.step {
            bounds::check_radial_load(bearing, &format!("operating.loads[{i}].after"), after)?;
        }
    }
    Ok(())
}

/// The message of a deserialisation error without toml's multi-line snippet.
fn serde_message(e: &toml::de::Error) -> String {
    let message = e.message().trim().replace('\n', " ");
    if message.starts_with("missing field") {
        message.replace("missing field", "missing key")
    } else if message.starts_with("unknown field") {
        message.replace("unknown field", "unknown key")
    } else {
        message
    }
}

/// Dotted key path from serde_path_to_error, e.g. `inner_ring.ribs[0].diameter`.
fn path_key(path: &serde_path_to_error::Path) -> String {
    use serde_path_to_error::Segment;
    let mut key = String::new();
    for segment in path.iter() {
        match segment {
            Segment::Map { key: k } => {
                if !key.is_empty() {
                    key.push('.');
                }
                key.push_str(k);
            }
            Segment::Seq { index } => key.push_str(&format!("[{index}]")),
            Segment::Enum { .. } | Segment::Unknown => {}
        }
    }
    key
}
