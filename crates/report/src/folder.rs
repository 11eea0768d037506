//! What an output folder holds: its manifest, plots and tables.

use crate::plain_svg::not_plain;
use crate::{MANIFEST_FILE, ReportError, RunKind, RunManifest};
use rolldyn_output::checksum_hex;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Largest CSV file shown as a table; larger ones (time series) are listed by size.
const MAX_TABLE_BYTES: u64 = 256 * 1024;

/// One SVG plot, its markup ready to inline.
pub struct Plot {
    pub name: String,
    pub svg: String,
}

/// An SVG file of the folder that is not inlined, and why: only what the run recorded in
/// `run.json`'s `files`, unchanged, is inlined (an SVG can hold scripts).
pub struct SkippedPlot {
    /// Path relative to the folder (`variants/v1-wear/depth.svg`).
    pub name: String,
    pub reason: String,
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
    /// The SVG files not inlined.
    pub skipped_plots: Vec<SkippedPlot>,
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
        let mut svg = SvgReader {
            dir,
            recorded: manifest.as_ref().and_then(|m| m.files.as_ref()),
            skipped: Vec::new(),
        };
        let sweep = match kind {
            RunKind::Sweep => Some(sweep_variants(&mut svg)?),
            _ => None,
        };
        let plots = svg.plots("")?;
        let skipped_plots = svg.skipped;
        Ok(Self {
            dir: dir.to_path_buf(),
            kind,
            manifest,
            plots,
            csv_files: csv_files(dir)?,
            sweep,
            skipped_plots,
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

/// The folders of `dir` whose plots a report shows, relative to it: the folder itself and the
/// output folders of a sweep's variants (`variants/<name>-wear`, `-fatigue`).
fn plot_folders(dir: &Path) -> Vec<String> {
    let mut folders = vec![String::new()];
    if let Ok(entries) = std::fs::read_dir(dir.join("variants")) {
        let mut variants: Vec<String> = entries
            .filter_map(Result::ok)
            .filter(|e| e.path().is_dir())
            .map(|e| format!("variants/{}/", e.file_name().to_string_lossy()))
            .collect();
        variants.sort();
        folders.extend(variants);
    }
    folders
}

/// The checksum ([`checksum_hex`]) of every SVG file a report of `dir` could inline, by path
/// relative to `dir` (`cage_slip.svg`, `variants/v1-wear/depth.svg`): what a run records in
/// its manifest's `files`.
pub fn plot_checksums(dir: &Path) -> Result<BTreeMap<String, String>, ReportError> {
    let mut sums = BTreeMap::new();
    for folder in plot_folders(dir) {
        for path in files_with(&dir.join(&folder), "svg")? {
            let bytes = std::fs::read(&path).map_err(|e| ReportError::io(&path, e))?;
            sums.insert(
                format!("{folder}{}", file_name(&path)),
                checksum_hex(&bytes),
            );
        }
    }
    Ok(sums)
}

/// Reads the SVG plots of a folder. With a manifest that lists its files, only those listed,
/// unchanged, are inlined; without (no `run.json`, or one of an older rolldyn), only plain
/// drawings ([`not_plain`]).
struct SvgReader<'a> {
    dir: &'a Path,
    /// The manifest's `files`.
    recorded: Option<&'a BTreeMap<String, String>>,
    skipped: Vec<SkippedPlot>,
}

impl SvgReader<'_> {
    /// Why the SVG file `name` (relative to the folder) with content `bytes` is not inlined.
    fn distrust(&self, name: &str, bytes: &[u8]) -> Option<String> {
        let Some(recorded) = self.recorded else {
            let text = String::from_utf8_lossy(bytes);
            let svg = text.find("<svg").map_or("", |start| &text[start..]);
            return not_plain(svg).map(|what| {
                format!(
                    "not a plain drawing ({what}) and no run.json lists it as written by rolldyn"
                )
            });
        };
        match recorded.get(name) {
            None => Some("not written by the run (run.json's files do not list it)".into()),
            Some(sum) if *sum != checksum_hex(bytes) => {
                Some("changed since the run wrote it (checksum mismatch with run.json)".into())
            }
            Some(_) => None,
        }
    }

    /// The plots of the subfolder `folder` (`""` or `variants/<name>/`), without their XML
    /// prologue; the files not trusted are noted in `skipped`.
    fn plots(&mut self, folder: &str) -> Result<Vec<Plot>, ReportError> {
        let mut plots = Vec::new();
        for path in files_with(&self.dir.join(folder), "svg")? {
            let bytes = std::fs::read(&path).map_err(|e| ReportError::io(&path, e))?;
            let name = file_name(&path);
            if let Some(reason) = self.distrust(&format!("{folder}{name}"), &bytes) {
                self.skipped.push(SkippedPlot {
                    name: format!("{folder}{name}"),
                    reason,
                });
                continue;
            }
            let text = String::from_utf8_lossy(&bytes);
            if let Some(start) = text.find("<svg") {
                plots.push(Plot {
                    name,
                    svg: text[start..].to_string(),
                });
            }
        }
        Ok(plots)
    }
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
fn sweep_variants(svg: &mut SvgReader<'_>) -> Result<(Table, Vec<Variant>), ReportError> {
    let dir = svg.dir;
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
            let own = format!("variants/{name}-{suffix}/");
            if dir.join(&own).is_dir() {
                variant_plots.extend(svg.plots(&own)?);
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
