//! What an output folder holds: its manifest, plots and tables.

use crate::{MANIFEST_FILE, ReportError, RunKind, RunManifest};
use std::path::{Path, PathBuf};

/// Largest CSV file shown as a table; larger ones (time series) are listed by size.
const MAX_TABLE_BYTES: u64 = 256 * 1024;

/// One SVG plot, its markup ready to inline.
pub struct Plot {
    pub name: String,
    pub svg: String,
}

/// A CSV file of the folder: its rows, or only its size when too large to show.
pub struct CsvFile {
    pub name: String,
    pub content: CsvContent,
}

pub enum CsvContent {
    Table(Table),
    TooLarge { bytes: u64 },
}

#[derive(Default)]
pub struct Table {
    pub header: Vec<String>,
    pub rows: Vec<Vec<String>>,
    /// The columns of the parameters a sweep varied (shown first, marked).
    pub varied: Vec<String>,
}

impl Table {
    /// The field of `row` in the column named `name`.
    pub fn field<'a>(&self, row: &'a [String], name: &str) -> Option<&'a str> {
        let column = self.header.iter().position(|h| h == name)?;
        row.get(column).map(String::as_str)
    }
}

/// A variant of a sweep: its row of `summary.csv` and the plots of its own output folder.
pub struct Variant {
    pub name: String,
    pub row: Vec<String>,
    pub plots: Vec<Plot>,
}

pub struct OutputFolder {
    pub dir: PathBuf,
    pub kind: RunKind,
    pub manifest: Option<RunManifest>,
    pub plots: Vec<Plot>,
    pub csv_files: Vec<CsvFile>,
    /// A sweep's `summary.csv` and its variants.
    pub sweep: Option<(Table, Vec<Variant>)>,
}

impl OutputFolder {
    pub fn read(dir: &Path) -> Result<Self, ReportError> {
        if !dir.is_dir() {
            return Err(ReportError::Folder {
                path: dir.to_path_buf(),
                reason: "no such output folder".into(),
            });
        }
        let manifest = RunManifest::read(dir)?;
        let kind = match &manifest {
            Some(m) => m.kind,
            None => inferred_kind(dir)?,
        };
        let sweep = match kind {
            RunKind::Sweep => Some(sweep_variants(dir)?),
            _ => None,
        };
        Ok(Self {
            dir: dir.to_path_buf(),
            kind,
            manifest,
            plots: plots(dir)?,
            csv_files: csv_files(dir)?,
            sweep,
        })
    }

    /// The model's name as the run's answer gives it.
    pub fn model_name(&self) -> Option<&str> {
        self.manifest.as_ref()?.summary.get("model")?.as_str()
    }
}

/// The kind of a folder without `run.json`, from the files each command writes.
fn inferred_kind(dir: &Path) -> Result<RunKind, ReportError> {
    let has = |name: &str| dir.join(name).exists();
    let kind = if has("summary.csv") && has("variants") {
        RunKind::Sweep
    } else if has("periods.csv") || has("tapered-windows.csv") {
        RunKind::Wear
    } else if has("damage-map.csv") || has("critical-history.csv") {
        RunKind::Fatigue
    } else if has("bearing.csv") || has("tapered.csv") {
        RunKind::Simulate
    } else {
        return Err(ReportError::Folder {
            path: dir.to_path_buf(),
            reason: format!(
                "not an output folder of simulate, sweep, wear or fatigue (no {MANIFEST_FILE} and none of their tables)"
            ),
        });
    };
    Ok(kind)
}

/// The files of `dir` ending in `.extension`, sorted by name.
fn files_with(dir: &Path, extension: &str) -> Result<Vec<PathBuf>, ReportError> {
    let entries = std::fs::read_dir(dir).map_err(|e| ReportError::io(dir, e))?;
    let mut files: Vec<PathBuf> = entries
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.is_file() && p.extension().is_some_and(|e| e == extension))
        .collect();
    files.sort();
    Ok(files)
}

fn file_name(path: &Path) -> String {
    path.file_name()
        .map_or(String::new(), |n| n.to_string_lossy().into_owned())
}

/// The SVG plots of `dir`, without their XML prologue.
fn plots(dir: &Path) -> Result<Vec<Plot>, ReportError> {
    let mut plots = Vec::new();
    for path in files_with(dir, "svg")? {
        let text = std::fs::read_to_string(&path).map_err(|e| ReportError::io(&path, e))?;
        if let Some(start) = text.find("<svg") {
            plots.push(Plot {
                name: file_name(&path),
                svg: text[start..].to_string(),
            });
        }
    }
    Ok(plots)
}

fn csv_files(dir: &Path) -> Result<Vec<CsvFile>, ReportError> {
    let mut files = Vec::new();
    for path in files_with(dir, "csv")? {
        let bytes = std::fs::metadata(&path)
            .map_err(|e| ReportError::io(&path, e))?
            .len();
        let content = match bytes <= MAX_TABLE_BYTES {
            true => CsvContent::Table(read_table(&path)?),
            false => CsvContent::TooLarge { bytes },
        };
        files.push(CsvFile {
            name: file_name(&path),
            content,
        });
    }
    Ok(files)
}

pub fn read_table(path: &Path) -> Result<Table, ReportError> {
    let bad = |e: csv::Error| ReportError::Io {
        path: path.to_path_buf(),
        reason: e.to_string(),
    };
    let mut reader = csv::ReaderBuilder::new()
        .flexible(true)
        .from_path(path)
        .map_err(bad)?;
    let header = reader
        .headers()
        .map_err(bad)?
        .iter()
        .map(String::from)
        .collect();
    let rows = reader
        .records()
        .map(|r| r.map(|r| r.iter().map(String::from).collect()))
        .collect::<Result<_, _>>()
        .map_err(bad)?;
    Ok(Table {
        header,
        rows,
        varied: Vec::new(),
    })
}

/// A sweep's `summary.csv` and, per row, the plots of `variants/<name>-wear` or `-fatigue`.
fn sweep_variants(dir: &Path) -> Result<(Table, Vec<Variant>), ReportError> {
    let summary = dir.join("summary.csv");
    let table = match summary.exists() {
        true => read_table(&summary)?,
        false => Table::default(),
    };
    let mut variants = Vec::new();
    for row in &table.rows {
        let name = table.field(row, "variant").unwrap_or_default().to_string();
        let mut variant_plots = Vec::new();
        for suffix in ["wear", "fatigue"] {
            let own = dir.join("variants").join(format!("{name}-{suffix}"));
            if own.is_dir() {
                variant_plots.extend(plots(&own)?);
            }
        }
        variants.push(Variant {
            name,
            row: row.clone(),
            plots: variant_plots,
        });
    }
    Ok((table, variants))
}
