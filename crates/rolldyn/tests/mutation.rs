//! Issue 39 "Stay fixed": a deterministic mutation test of every input format rolldyn reads —
//! model, sweep, oil, journal, S–N curve, rainflow history, cage loads, raceway wear maps, the
//! designation of `rolldyn new`, the duty-cycle rows of `rolldyn life` and the material keys of a
//! model. Mutants of example inputs (a deleted line, a wrong unit, an extreme number, a
//! truncation, random bytes, a duplicated table or line) go through the typed library API, in
//! process, as the command line would run them; the failure's type gives the exit code the
//! program would return (`Failure::exit_code`). Every mutant is classified:
//!
//! - exit 0, *plausible*: accepted; no number of the result may be non-finite (a raw NaN or ±∞
//!   in the serialised result: the JSON writer would print a `null` without reason) unless a
//!   `non_finite` object beside it gives the reason;
//! - exit 2, *located*: refused as bad input by a message that names where ([`located`]): for
//!   a keyed file (TOML, JSON) `FILE:LINE`, or the file with `line N`, or a key of it; for a
//!   table (CSV, Parquet) the file; for a command-line value the value itself or its flag;
//! - exit 1, *diagnosed*: a numerical failure with a message.
//!
//! A panic, a hang (a mutant running longer than [`HANG`]), a non-finite number with exit 0 or
//! an exit-2 message without a location fails the test, unless the mutant is listed in
//! [`KNOWN_OPEN`] with the defect that will fix it. The cargo-fuzz targets in fuzz/ explore
//! further; this is what CI runs.

use rolldyn::fatigue::{FatigueRequest, Rainflow};
use rolldyn::life::{DutyRow, Life, LifeRequest};
use rolldyn::{Analysis, Context, Failure, ModelSource, Unobserved};
use serde::Serialize;
use serde_json::{Value, json};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::{OnceLock, mpsc};
use std::time::{Duration, Instant};

/// A mutant running longer than this hangs.
const HANG: Duration = Duration::from_secs(10);

/// Mutants that break a guarantee today, each with the defect (docs: issue 39) whose fix makes
/// it pass: `(format, mutant index, defect)`. The lead removes an entry when its fix merges; a
/// listed mutant that passes fails the test too, so that the list cannot go stale.
const KNOWN_OPEN: &[(&str, usize, &str)] = &[];

/// Extreme numbers written in place of a number.
const EXTREMES: [&str; 14] = [
    "0",
    "-1",
    "1e308",
    "-1e308",
    "1e-308",
    "5e-324",
    "nan",
    "inf",
    "-inf",
    "1e30",
    "1e-30",
    "18446744073709551616",
    "-0.0",
    "1e999",
];

/// Units written in place of a unit.
const UNITS: [&str; 12] = [
    "mm", "kg", "rpm", "N", "C", "GPa", "um", "s", "kg/m3", "rad", "h", "mm2/s",
];

/// Names written in place of a quoted text: materials, laws, kinds, nothing.
const NAMES: [&str; 10] = [
    "",
    "unobtainium",
    "aisi-4340",
    "pa66-gf25",
    "peek",
    "cuzn40pb2",
    "40khn2ma-sh",
    "silver",
    "barus",
    "x y",
];

/// xorshift64*: a seeded generator, so that every run tests the same mutants.
struct Rng(u64);

impl Rng {
    /// The generator of the format `name` (seeded by the FNV-1a hash of the name).
    fn for_format(name: &str) -> Self {
        let hash = name.bytes().fold(0xCBF2_9CE4_8422_2325_u64, |h, b| {
            (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01B3)
        });
        Self(hash | 1)
    }

    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }

    fn pick<'a>(&mut self, items: &[&'a str]) -> &'a str {
        items[self.below(items.len())]
    }
}

// ---------------------------------------------------------------------------------------------
// Mutators

/// A number in `text` replaced by `by` (the first run of digits, sign and exponent from a
/// random digit on).
fn replace_number(text: &str, by: &str, rng: &mut Rng) -> Option<String> {
    let digits: Vec<usize> = text
        .char_indices()
        .filter(|&(i, c)| {
            c.is_ascii_digit()
                && !text[..i]
                    .chars()
                    .next_back()
                    .is_some_and(|p| p.is_ascii_digit() || p == '.')
        })
        .map(|(i, _)| i)
        .collect();
    let start = *digits.get(rng.below(digits.len()))?;
    let end = text[start..]
        .find(|c: char| !(c.is_ascii_digit() || ".eE+-".contains(c)))
        .map_or(text.len(), |e| start + e);
    Some(format!("{}{by}{}", &text[..start], &text[end..]))
}

/// The unit after a number replaced by another unit: in a quoted value (`"5 mm"`) or glued to
/// a number (`15kN`).
fn replace_unit(text: &str, by: &str, rng: &mut Rng) -> Option<String> {
    let bytes = text.as_bytes();
    let starts: Vec<usize> = (1..bytes.len())
        .filter(|&i| {
            bytes[i].is_ascii_alphabetic()
                && (bytes[i - 1].is_ascii_digit()
                    || (bytes[i - 1] == b' ' && i >= 2 && bytes[i - 2].is_ascii_digit()))
        })
        .collect();
    let start = *starts.get(rng.below(starts.len()))?;
    let end = text[start..]
        .find(['"', ',', '\n', ' ', ']', '}'])
        .map_or(text.len(), |e| start + e);
    Some(format!("{}{by}{}", &text[..start], &text[end..]))
}

/// The first quoted text of `line` replaced by `by`.
fn replace_quoted(line: &str, by: &str) -> Option<String> {
    let open = line.find('"')?;
    let close = open + 1 + line[open + 1..].find('"')?;
    Some(format!("{}{by}{}", &line[..=open], &line[close..]))
}

/// A `[table]` (or, in a file without tables, a line) duplicated after itself.
fn duplicate_block(lines: &[String], rng: &mut Rng) -> Option<Vec<String>> {
    let headers: Vec<usize> = (0..lines.len())
        .filter(|&i| lines[i].starts_with('['))
        .collect();
    let (start, end) = if headers.is_empty() {
        let i = rng.below(lines.len());
        (i, i + 1)
    } else {
        let start = headers[rng.below(headers.len())];
        let end = (start + 1..lines.len())
            .find(|&i| lines[i].starts_with('['))
            .unwrap_or(lines.len());
        (start, end)
    };
    let mut out = lines[..end].to_vec();
    out.extend_from_slice(&lines[start..end]);
    out.extend_from_slice(&lines[end..]);
    Some(out)
}

/// One mutant of a file's `text` restricted to the lines `focus` allows, and what was done.
fn mutate_file(text: &str, focus: fn(&str) -> bool, rng: &mut Rng) -> (String, String) {
    let lines: Vec<String> = text.split_inclusive('\n').map(str::to_string).collect();
    let focused: Vec<usize> = (0..lines.len())
        .filter(|&i| focus(&lines[i]) && !lines[i].trim_start().starts_with('#'))
        .collect();
    loop {
        let i = focused[rng.below(focused.len())];
        let mut out = lines.clone();
        let what = match rng.below(7) {
            0 => {
                out.remove(i);
                Some(format!("deleted line {}", i + 1))
            }
            1 => {
                let unit = rng.pick(&UNITS);
                replace_unit(&lines[i], unit, rng).map(|l| {
                    out[i] = l;
                    format!("unit of line {} → {unit}", i + 1)
                })
            }
            2 => {
                let number = rng.pick(&EXTREMES);
                replace_number(&lines[i], number, rng).map(|l| {
                    out[i] = l;
                    format!("number of line {} → {number}", i + 1)
                })
            }
            3 => {
                let joined = lines.concat();
                let mut at = rng.below(joined.len());
                while !joined.is_char_boundary(at) {
                    at -= 1;
                }
                out = vec![joined[..at].to_string()];
                Some(format!("truncated at byte {at}"))
            }
            4 => {
                let (bytes, n) = random_bytes(lines.concat().into_bytes(), rng);
                out = vec![String::from_utf8_lossy(&bytes).into_owned()];
                Some(format!("{n} random bytes"))
            }
            5 => duplicate_block(&lines, rng).map(|l| {
                out = l;
                "duplicated a table or line".to_string()
            }),
            _ => {
                let name = rng.pick(&NAMES);
                replace_quoted(&lines[i], name).map(|l| {
                    out[i] = l;
                    format!("text of line {} → '{name}'", i + 1)
                })
            }
        };
        if let Some(what) = what
            && out.concat() != text
        {
            return (out.concat(), what);
        }
    }
}

/// 1 to 8 bytes of `bytes` overwritten by random ones.
fn random_bytes(mut bytes: Vec<u8>, rng: &mut Rng) -> (Vec<u8>, usize) {
    let n = 1 + rng.below(8);
    for _ in 0..n {
        let at = rng.below(bytes.len());
        bytes[at] = rng.next() as u8;
    }
    (bytes, n)
}

/// One mutant of a command-line value (a designation, a duty row) and what was done.
fn mutate_value(text: &str, rng: &mut Rng) -> (String, String) {
    const CHARS: &[u8] = b"0123456789NUJPX =,.-+e ";
    loop {
        let chars: Vec<char> = text.chars().collect();
        let at = rng.below(chars.len());
        let (out, what) = match rng.below(7) {
            0 => {
                let mut c = chars.clone();
                c.remove(at);
                (c.into_iter().collect(), format!("deleted char {at}"))
            }
            1 => {
                let mut c = chars.clone();
                c.insert(at, CHARS[rng.below(CHARS.len())] as char);
                (c.into_iter().collect(), format!("inserted a char at {at}"))
            }
            2 => {
                let number = rng.pick(&EXTREMES);
                match replace_number(text, number, rng) {
                    Some(t) => (t, format!("a number → {number}")),
                    None => continue,
                }
            }
            3 => {
                let unit = rng.pick(&UNITS);
                match replace_unit(text, unit, rng) {
                    Some(t) => (t, format!("a unit → {unit}")),
                    None => continue,
                }
            }
            4 => (
                chars[..at].iter().collect(),
                format!("truncated at char {at}"),
            ),
            5 => {
                let (bytes, n) = random_bytes(text.as_bytes().to_vec(), rng);
                (
                    String::from_utf8_lossy(&bytes).into_owned(),
                    format!("{n} random bytes"),
                )
            }
            _ => {
                let parts: Vec<&str> = text.split(',').collect();
                let i = rng.below(parts.len());
                let mut doubled = parts.clone();
                doubled.insert(i, parts[i]);
                (doubled.join(","), format!("duplicated part {i}"))
            }
        };
        if out != text {
            return (out, what);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Non-finite numbers in a result

/// The paths of the non-finite numbers of `value` as serialised (what `--json` would print as
/// a `null` without a reason: results replace their non-finite values by a `null` and a
/// `non_finite` reason before serialising).
fn non_finite_numbers(value: &impl Serialize) -> Vec<String> {
    let mut walker = walker::Walker::default();
    value
        .serialize(&mut walker)
        .expect("the walker never fails");
    walker
        .found
        .into_iter()
        .map(|(path, value)| format!("{path} = {value}"))
        .collect()
}

mod walker {
    //! A serde serializer that writes nothing and records where a float is not finite.
    use rolldyn_output::non_finite::NON_FINITE_KEY;
    use serde::ser::{self, Serialize};
    use std::fmt;

    #[derive(Default)]
    pub struct Walker {
        path: Vec<String>,
        /// `(path, value)` of every non-finite float.
        pub found: Vec<(String, f64)>,
    }

    #[derive(Debug)]
    pub struct Never;

    impl fmt::Display for Never {
        fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
            f.write_str("never")
        }
    }

    impl std::error::Error for Never {}

    impl ser::Error for Never {
        fn custom<T: fmt::Display>(_: T) -> Self {
            Never
        }
    }

    type R = Result<(), Never>;

    impl Walker {
        fn float(&mut self, v: f64) -> R {
            if !v.is_finite() {
                self.found.push((self.path.join("."), v));
            }
            Ok(())
        }

        fn at<T: Serialize + ?Sized>(&mut self, key: String, value: &T) -> R {
            self.path.push(key);
            value.serialize(&mut *self)?;
            self.path.pop();
            Ok(())
        }
    }

    macro_rules! ignore {
        ($($name:ident: $t:ty),*) => {
            $(fn $name(self, _: $t) -> R { Ok(()) })*
        };
    }

    impl<'a> ser::Serializer for &'a mut Walker {
        type Ok = ();
        type Error = Never;
        type SerializeSeq = Seq<'a>;
        type SerializeTuple = Seq<'a>;
        type SerializeTupleStruct = Seq<'a>;
        type SerializeTupleVariant = Seq<'a>;
        type SerializeMap = Seq<'a>;
        type SerializeStruct = Seq<'a>;
        type SerializeStructVariant = Seq<'a>;

        ignore!(serialize_bool: bool, serialize_i8: i8, serialize_i16: i16, serialize_i32: i32,
            serialize_i64: i64, serialize_u8: u8, serialize_u16: u16, serialize_u32: u32,
            serialize_u64: u64, serialize_char: char, serialize_str: &str,
            serialize_bytes: &[u8], serialize_unit_struct: &'static str);

        fn serialize_f32(self, v: f32) -> R {
            self.float(f64::from(v))
        }
        fn serialize_f64(self, v: f64) -> R {
            self.float(v)
        }
        fn serialize_none(self) -> R {
            Ok(())
        }
        fn serialize_some<T: Serialize + ?Sized>(self, v: &T) -> R {
            v.serialize(self)
        }
        fn serialize_unit(self) -> R {
            Ok(())
        }
        fn serialize_unit_variant(self, _: &'static str, _: u32, _: &'static str) -> R {
            Ok(())
        }
        fn serialize_newtype_struct<T: Serialize + ?Sized>(self, _: &'static str, v: &T) -> R {
            v.serialize(self)
        }
        fn serialize_newtype_variant<T: Serialize + ?Sized>(
            self,
            _: &'static str,
            _: u32,
            variant: &'static str,
            v: &T,
        ) -> R {
            self.at(variant.to_string(), v)
        }
        fn serialize_seq(self, _: Option<usize>) -> Result<Seq<'a>, Never> {
            Ok(Seq::new(self))
        }
        fn serialize_tuple(self, _: usize) -> Result<Seq<'a>, Never> {
            Ok(Seq::new(self))
        }
        fn serialize_tuple_struct(self, _: &'static str, _: usize) -> Result<Seq<'a>, Never> {
            Ok(Seq::new(self))
        }
        fn serialize_tuple_variant(
            self,
            _: &'static str,
            _: u32,
            _: &'static str,
            _: usize,
        ) -> Result<Seq<'a>, Never> {
            Ok(Seq::new(self))
        }
        fn serialize_map(self, _: Option<usize>) -> Result<Seq<'a>, Never> {
            Ok(Seq::new(self))
        }
        fn serialize_struct(self, _: &'static str, _: usize) -> Result<Seq<'a>, Never> {
            Ok(Seq::new(self))
        }
        fn serialize_struct_variant(
            self,
            _: &'static str,
            _: u32,
            _: &'static str,
            _: usize,
        ) -> Result<Seq<'a>, Never> {
            Ok(Seq::new(self))
        }
    }

    /// A compound value: its elements are walked with their index or key on the path; the keys
    /// its `non_finite` object gives a reason for are not reported (docs/outputs.md).
    pub struct Seq<'a> {
        walker: &'a mut Walker,
        index: usize,
        key: String,
        /// `walker.found` before this value
        found_before: usize,
        /// the keys of this value's `non_finite` object
        explained: Vec<String>,
    }

    impl<'a> Seq<'a> {
        fn new(walker: &'a mut Walker) -> Self {
            let found_before = walker.found.len();
            Self {
                walker,
                index: 0,
                key: String::new(),
                found_before,
                explained: Vec::new(),
            }
        }

        /// Walks the member `key`: a `non_finite` object is read, not walked.
        fn member<T: Serialize + ?Sized>(&mut self, key: String, v: &T) -> R {
            if key == NON_FINITE_KEY {
                if let Ok(serde_json::Value::Object(reasons)) = serde_json::to_value(v) {
                    self.explained.extend(reasons.keys().cloned());
                }
                return Ok(());
            }
            self.walker.at(key, v)
        }

        /// Drops the values of this member the `non_finite` object explains.
        fn finish(self) -> R {
            let prefix = self.walker.path.join(".");
            let explained: Vec<String> = self
                .explained
                .iter()
                .map(|k| {
                    if prefix.is_empty() {
                        k.clone()
                    } else {
                        format!("{prefix}.{k}")
                    }
                })
                .collect();
            let mut index = self.found_before;
            while index < self.walker.found.len() {
                if explained.contains(&self.walker.found[index].0) {
                    self.walker.found.remove(index);
                } else {
                    index += 1;
                }
            }
            Ok(())
        }

        fn element<T: Serialize + ?Sized>(&mut self, v: &T) -> R {
            let key = self.index.to_string();
            self.index += 1;
            self.walker.at(key, v)
        }
    }

    /// A map key as text (keys are strings or numbers in rolldyn's results).
    struct KeyText(String);

    impl ser::Serializer for &mut KeyText {
        type Ok = ();
        type Error = Never;
        type SerializeSeq = ser::Impossible<(), Never>;
        type SerializeTuple = ser::Impossible<(), Never>;
        type SerializeTupleStruct = ser::Impossible<(), Never>;
        type SerializeTupleVariant = ser::Impossible<(), Never>;
        type SerializeMap = ser::Impossible<(), Never>;
        type SerializeStruct = ser::Impossible<(), Never>;
        type SerializeStructVariant = ser::Impossible<(), Never>;

        fn serialize_str(self, v: &str) -> R {
            self.0 = v.to_string();
            Ok(())
        }
        fn serialize_u64(self, v: u64) -> R {
            self.0 = v.to_string();
            Ok(())
        }
        fn serialize_i64(self, v: i64) -> R {
            self.0 = v.to_string();
            Ok(())
        }
        ignore!(serialize_bool: bool, serialize_i8: i8, serialize_i16: i16, serialize_i32: i32,
            serialize_u8: u8, serialize_u16: u16, serialize_u32: u32, serialize_f32: f32,
            serialize_f64: f64, serialize_char: char, serialize_bytes: &[u8],
            serialize_unit_struct: &'static str);
        fn serialize_none(self) -> R {
            Ok(())
        }
        fn serialize_some<T: Serialize + ?Sized>(self, v: &T) -> R {
            v.serialize(self)
        }
        fn serialize_unit(self) -> R {
            Ok(())
        }
        fn serialize_unit_variant(self, _: &'static str, _: u32, name: &'static str) -> R {
            self.0 = name.to_string();
            Ok(())
        }
        fn serialize_newtype_struct<T: Serialize + ?Sized>(self, _: &'static str, v: &T) -> R {
            v.serialize(self)
        }
        fn serialize_newtype_variant<T: Serialize + ?Sized>(
            self,
            _: &'static str,
            _: u32,
            _: &'static str,
            _: &T,
        ) -> R {
            Ok(())
        }
        fn serialize_seq(self, _: Option<usize>) -> Result<Self::SerializeSeq, Never> {
            Err(Never)
        }
        fn serialize_tuple(self, _: usize) -> Result<Self::SerializeTuple, Never> {
            Err(Never)
        }
        fn serialize_tuple_struct(
            self,
            _: &'static str,
            _: usize,
        ) -> Result<Self::SerializeTupleStruct, Never> {
            Err(Never)
        }
        fn serialize_tuple_variant(
            self,
            _: &'static str,
            _: u32,
            _: &'static str,
            _: usize,
        ) -> Result<Self::SerializeTupleVariant, Never> {
            Err(Never)
        }
        fn serialize_map(self, _: Option<usize>) -> Result<Self::SerializeMap, Never> {
            Err(Never)
        }
        fn serialize_struct(
            self,
            _: &'static str,
            _: usize,
        ) -> Result<Self::SerializeStruct, Never> {
            Err(Never)
        }
        fn serialize_struct_variant(
            self,
            _: &'static str,
            _: u32,
            _: &'static str,
            _: usize,
        ) -> Result<Self::SerializeStructVariant, Never> {
            Err(Never)
        }
    }

    macro_rules! elements {
        ($($tr:ident :: $method:ident),*) => {
            $(impl ser::$tr for Seq<'_> {
                type Ok = ();
                type Error = Never;
                fn $method<T: Serialize + ?Sized>(&mut self, v: &T) -> R {
                    self.element(v)
                }
                fn end(self) -> R {
                    Ok(())
                }
            })*
        };
    }

    elements!(
        SerializeSeq::serialize_element,
        SerializeTuple::serialize_element,
        SerializeTupleStruct::serialize_field,
        SerializeTupleVariant::serialize_field
    );

    impl ser::SerializeMap for Seq<'_> {
        type Ok = ();
        type Error = Never;
        fn serialize_key<T: Serialize + ?Sized>(&mut self, key: &T) -> R {
            let mut text = KeyText(String::new());
            // a key that is no string or number is named by its position
            if key.serialize(&mut text).is_err() {
                text.0 = self.index.to_string();
            }
            self.key = text.0;
            Ok(())
        }
        fn serialize_value<T: Serialize + ?Sized>(&mut self, v: &T) -> R {
            self.index += 1;
            let key = std::mem::take(&mut self.key);
            self.member(key, v)
        }
        fn end(self) -> R {
            self.finish()
        }
    }

    macro_rules! fields {
        ($($tr:ident),*) => {
            $(impl ser::$tr for Seq<'_> {
                type Ok = ();
                type Error = Never;
                fn serialize_field<T: Serialize + ?Sized>(&mut self, key: &'static str, v: &T) -> R {
                    self.member(key.to_string(), v)
                }
                fn end(self) -> R {
                    self.finish()
                }
            })*
        };
    }

    fields!(SerializeStruct, SerializeStructVariant);
}

// ---------------------------------------------------------------------------------------------
// Running a mutant

/// What a mutant did, short of a broken guarantee the harness detects (panic, hang).
type Outcome = Result<Vec<String>, Failure>;

/// Runs analysis `A` on `request` (JSON) with `model`, as the command line does; the non-finite
/// numbers of its result.
fn analyse<A: Analysis>(request: Value, model: Option<&Path>) -> Outcome {
    let request: A::Request =
        serde_json::from_value(request).unwrap_or_else(|e| panic!("test request: {e}"));
    let context = Context::new(ModelSource::file_or_embedded(model), &Unobserved);
    let result = A::run(&request, &context)?;
    Ok(non_finite_numbers(&result))
}

/// Where an exit-2 message must point.
#[derive(Clone, Copy)]
enum Location {
    /// A keyed file (TOML, JSON): `NAME:LINE`, `NAME: line LINE` or NAME with a later `line N`,
    /// or one of the seed's keys (keys and the parts of table names) or of these keys.
    Keyed(&'static [&'static str]),
    /// A table of rows (CSV, Parquet): its name (a row's error names its line too, a count of
    /// rows or a damaged Parquet file have none).
    Table,
    /// A command-line value: the value itself, quoted in the message, or one of these flags
    /// and keys.
    Value(&'static [&'static str]),
}

/// The keys of a seed file a message may name: TOML keys and the parts of table names, JSON
/// object keys; at least 3 characters long.
fn keys_of(text: &str) -> Vec<String> {
    let mut keys = Vec::new();
    for line in text.lines().map(str::trim) {
        let names = if let Some(table) = line.strip_prefix('[') {
            table.trim_matches(|c| c == '[' || c == ']')
        } else if let Some((key, _)) = line.split_once(['=', ':']) {
            key
        } else {
            continue;
        };
        keys.extend(
            names
                .split(['.', '"', ' '])
                .filter(|k| k.len() >= 3 && !k.starts_with('#'))
                .map(str::to_string),
        );
    }
    keys.sort();
    keys.dedup();
    keys
}

/// Whether `word` occurs in `text` as a whole word (not inside a longer name).
fn contains_word(text: &str, word: &str) -> bool {
    let name_char = |c: char| c.is_ascii_alphanumeric() || c == '_';
    text.match_indices(word).any(|(at, _)| {
        !text[..at].chars().next_back().is_some_and(name_char)
            && !text[at + word.len()..]
                .chars()
                .next()
                .is_some_and(name_char)
    })
}

/// Whether `message`, refusing the mutant `input` (its file's path or its value), says where;
/// `keys` are the seed file's keys.
fn located(message: &str, location: Location, input: &str, keys: &[String]) -> bool {
    let name = Path::new(input)
        .file_name()
        .map(|n| n.to_string_lossy().to_string())
        .unwrap_or_default();
    let named = !name.is_empty() && message.contains(&name);
    match location {
        Location::Keyed(extra) => {
            let line = message
                .split("line ")
                .skip(1)
                .any(|rest| rest.starts_with(|c: char| c.is_ascii_digit()));
            let at_line = message.match_indices(&name).any(|(at, _)| {
                message[at + name.len()..]
                    .strip_prefix(':')
                    .is_some_and(|rest| rest.starts_with(|c: char| c.is_ascii_digit()))
            });
            at_line
                || (named && line)
                || keys.iter().any(|k| contains_word(message, k))
                || extra.iter().any(|k| message.contains(k))
        }
        Location::Table => named,
        Location::Value(keys) => {
            (!input.trim().is_empty() && message.contains(input.trim()))
                || keys.iter().any(|k| message.contains(k))
        }
    }
}

/// One input format: its example inputs, how a mutant is made and run, where a refusal must
/// point.
struct Format {
    name: &'static str,
    /// `(file name, text)` of the example inputs (values for [`Location::Value`] formats).
    seeds: Vec<(String, String)>,
    mutants: usize,
    /// The lines of a seed that mutants change (all but comments unless restricted).
    focus: fn(&str) -> bool,
    location: Location,
    /// Runs a mutant: the path of the mutant file (or the value) and the mutant's index.
    run: fn(&str, usize) -> Outcome,
}

fn any_line(_: &str) -> bool {
    true
}

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

fn example(name: &str) -> String {
    let text = std::fs::read_to_string(examples().join(name)).unwrap();
    // relative paths inside a seed point at the examples from wherever the mutant is written
    text.replace(
        "\"oils/",
        &format!("\"{}/", examples().join("oils").display()),
    )
    .replace(
        "\"../2002834.toml\"",
        &format!("\"{}\"", examples().join("2002834.toml").display()),
    )
}

/// The scratch folder of this test run.
fn scratch() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-mutation-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Every this many plausible model mutants also run a quasi-static skid point.
const SKID_EVERY: usize = 4;

fn run_model(path: &str, index: usize) -> Outcome {
    let found = analyse::<rolldyn::check::Check>(json!({}), Some(Path::new(path)))?;
    if !found.is_empty() || !index.is_multiple_of(SKID_EVERY) {
        return Ok(found);
    }
    // skid solves complete cylindrical bearings (it refuses the others by the model's name)
    let model = rolldyn_model::load(Path::new(path))?;
    let complete = model
        .bearing
        .require_cylindrical("skid")
        .is_ok_and(|b| b.cage.is_some());
    if !complete {
        return Ok(found);
    }
    analyse::<rolldyn::skid::Skid>(json!({}), Some(Path::new(path)))
}

fn run_material(path: &str, index: usize) -> Outcome {
    let mut found = run_model(path, index)?;
    // the cage's S–N curve as `fatigue` resolves it, on a range of amplitudes
    let model = rolldyn_model::load(Path::new(path))?;
    let Ok(bearing) = model.bearing.require_cylindrical("fatigue") else {
        return Ok(found);
    };
    let settings = serde_json::from_value::<FatigueRequest>(json!({"mean_stress": "goodman"}))
        .unwrap()
        .settings()?;
    let material = rolldyn_fatigue::cage_material::CageMaterial::of(bearing);
    let used = rolldyn_fatigue::cage_material::resolve(
        material.as_ref(),
        &settings.sn,
        settings.mean_stress,
    )
    .map_err(Failure::Input)?;
    found.extend(non_finite_numbers(&used));
    found.extend(curve_values(&used.curve));
    Ok(found)
}

/// The curve's cycles to failure and allowable amplitudes over its range: NaN is never an
/// answer (∞ is: no damage).
fn curve_values(curve: &rolldyn_fatigue::sn::SnCurve) -> Vec<String> {
    let mut found = Vec::new();
    for amplitude in [1e5, 1e7, 1e8, 3e8, 1e9, 1e10] {
        let n = curve.cycles_to_failure(amplitude);
        if n.is_nan() {
            found.push(format!("cycles_to_failure({amplitude}) = {n}"));
        }
    }
    for cycles in [1.0, 1e3, 1e6, 1e9, 1e12] {
        let a = curve.allowable_amplitude(cycles);
        if !a.is_finite() {
            found.push(format!("allowable_amplitude({cycles}) = {a}"));
        }
    }
    found
}

/// Every this many oil mutants `oils` accepts also lubricate a skid point of bearing 2002834.
const OIL_SKID_EVERY: usize = 3;

fn run_oil(path: &str, index: usize) -> Outcome {
    let found = analyse::<rolldyn::oils::Oils>(json!({"oil_file": path}), None)?;
    if !found.is_empty() || !index.is_multiple_of(OIL_SKID_EVERY) {
        return Ok(found);
    }
    let text = example("2002834.toml");
    let (start, end) = (
        text.find("[lubricant]").unwrap(),
        text.find("[operating]").unwrap(),
    );
    let model = Path::new(path).with_extension("model.toml");
    std::fs::write(
        &model,
        format!(
            "{}[lubricant]\nfile = \"{path}\"\n\n{}",
            &text[..start],
            &text[end..]
        ),
    )
    .unwrap();
    analyse::<rolldyn::skid::Skid>(json!({}), Some(&model))
}

fn run_journal(path: &str, _: usize) -> Outcome {
    analyse::<rolldyn::journal::Journal>(json!({"file": path}), None)
}

fn run_sweep(path: &str, _: usize) -> Outcome {
    rolldyn_sweep::SweepFile::load(Path::new(path)).map_err(|e| Failure::Input(e.to_string()))?;
    Ok(Vec::new())
}

fn run_sn_curve(path: &str, _: usize) -> Outcome {
    let settings = serde_json::from_value::<FatigueRequest>(json!({"sn_curve": path}))
        .unwrap()
        .settings()?;
    let (curve, _) = settings.sn.curve.expect("the curve given");
    Ok(curve_values(&curve))
}

fn run_rainflow(path: &str, _: usize) -> Outcome {
    analyse::<Rainflow>(json!({"history": path}), None)
}

/// The header mutant `NAME.json` with the unchanged load table beside it.
fn run_cage_loads(header: &str, _: usize) -> Outcome {
    let table = Path::new(header).with_extension("parquet");
    std::fs::copy(cage_loads().with_extension("parquet"), &table).unwrap();
    analyse::<rolldyn::fatigue::Fatigue>(json!({"loads": table}), None)
}

/// The load-table mutant `NAME.parquet` with the unchanged header beside it.
fn run_cage_table(table: &str, _: usize) -> Outcome {
    let table = Path::new(table);
    std::fs::copy(
        cage_loads().with_extension("json"),
        table.with_extension("json"),
    )
    .unwrap();
    analyse::<rolldyn::fatigue::Fatigue>(json!({"loads": table}), None)
}

/// A cage-load export of bearing 2002834 (written once per test run): one revolution of 180
/// sets, each roller pressing on its pocket's bar and the cage on its land, the forces varying
/// around the revolution. The path of its header (`loads.json`, the table `loads.parquet`).
fn cage_loads() -> PathBuf {
    static EXPORT: OnceLock<PathBuf> = OnceLock::new();
    EXPORT
        .get_or_init(|| {
            use rolldyn_fatigue::{
                CageLoadExport, ContactKind, ContactLoad, LoadSet, SETS_PER_REVOLUTION,
            };
            let model = rolldyn_model::load(&examples().join("2002834.toml")).unwrap();
            let bearing = model.bearing.require_cylindrical("test").unwrap();
            let cage = rolldyn_fatigue::study::cage_geometry(bearing, None).unwrap();
            let z = bearing.roller.bar_contact_half_span();
            let header = rolldyn_fatigue::study::export_header(
                "2002834.toml",
                &cage,
                rolldyn_fatigue::cage_material::CageMaterial::of(bearing),
                z,
                400.0,
            );
            let sets = (0..SETS_PER_REVOLUTION)
                .map(|i| {
                    let angle = (2 * i) as f64;
                    let phase = angle.to_radians();
                    let contacts = (0..cage.pockets)
                        .flat_map(|pocket| {
                            let load = 20.0 + 15.0 * (phase + pocket as f64).sin();
                            [
                                ContactLoad {
                                    kind: ContactKind::Bar,
                                    pocket,
                                    location: 2,
                                    force_n: [0.0, load, 0.0],
                                    point_m: [cage.pitch_radius, 0.0, z],
                                },
                                ContactLoad {
                                    kind: ContactKind::Land,
                                    pocket,
                                    location: 0,
                                    force_n: [-0.5 * load, 0.0, 0.0],
                                    point_m: [cage.outer_radius, 0.0, -z],
                                },
                            ]
                        })
                        .collect();
                    LoadSet {
                        cage_angle_deg: angle,
                        time_s: phase / 400.0,
                        acceleration_m_s2: [1.0, 0.5, 0.0],
                        angular_velocity_rad_s: [0.0, 0.0, 400.0],
                        angular_acceleration_rad_s2: [0.0, 0.0, 10.0],
                        contacts,
                    }
                })
                .collect();
            let dir = scratch().join("fixture");
            std::fs::create_dir_all(&dir).unwrap();
            let table = dir.join("loads.parquet");
            CageLoadExport { header, sets }.write(&table).unwrap();
            table.with_extension("json")
        })
        .clone()
}

fn run_designation(value: &str, _: usize) -> Outcome {
    analyse::<rolldyn::new_model::NewModel>(json!({"designation": value}), None)
}

fn run_duty(value: &str, _: usize) -> Outcome {
    // the command line parses the row (clap names --duty when it is refused)
    let rows = value
        .split(';')
        .map(str::parse::<DutyRow>)
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| Failure::Input(format!("--duty: {e}")))?;
    let request = LifeRequest {
        duty: rows,
        ..LifeRequest::default()
    };
    let context = Context::new(
        ModelSource::File(examples().join("2002834.toml")),
        &Unobserved,
    );
    let result = Life::run(&request, &context)?;
    Ok(non_finite_numbers(&result))
}

// ---------------------------------------------------------------------------------------------
// The formats

/// The lines of a model that carry materials: `[materials.*]` tables and `material` keys.
fn material_line(line: &str) -> bool {
    let l = line.trim_start();
    l.split('=')
        .next()
        .is_some_and(|key| key.contains("material"))
        || l.starts_with("[materials")
        || l.starts_with("sn_curve")
        || l.starts_with("ultimate_strength")
        || l.starts_with("fatigue_like")
        || l.starts_with("youngs_modulus")
        || l.starts_with("density")
        || l.starts_with("poisson")
        || l.starts_with("meyer_hardness")
}

/// Bearing 2002834 whose cage material has its own S–N curve and σ_u instead of `fatigue_like`.
fn own_sn_curve() -> String {
    let text = example("2002834.toml");
    let line = text
        .lines()
        .find(|l| l.starts_with("fatigue_like"))
        .expect("2002834.toml: the cage steel is fatigue_like a built-in one");
    text.replace(
        line,
        "ultimate_strength = \"1100 MPa\"\nsn_curve = { cycles = [1e3, 1e6, 1e7], amplitude = \
         [\"900 MPa\", \"480 MPa\", \"380 MPa\"], source = \"mutation test\" }",
    )
}

/// A raceway wear map of 4 axial lines × 12 angle bins.
fn wear_map() -> String {
    let mut text = String::from("axial_mm,angle_deg,depth_um\n");
    for x in [-4.0, -1.5, 1.5, 4.0] {
        for k in 0..12 {
            let depth = 0.5 + 0.1 * k as f64 - 0.05 * x;
            text.push_str(&format!("{x},{},{depth:.3}\n", (k as f64 + 0.5) * 30.0));
        }
    }
    text
}

fn formats() -> Vec<Format> {
    let seeds = |names: &[&str]| -> Vec<(String, String)> {
        names
            .iter()
            .map(|n| {
                let file = Path::new(n)
                    .file_name()
                    .unwrap()
                    .to_string_lossy()
                    .to_string();
                (file, example(n))
            })
            .collect()
    };
    vec![
        Format {
            name: "model",
            seeds: seeds(&[
                "2002834.toml",
                "1032930.toml",
                "obrien-taylor.toml",
                "tapered-cassette.toml",
                "contact/32206-straight.toml",
            ]),
            mutants: 250,
            focus: any_line,
            location: Location::Keyed(&[]),
            run: run_model,
        },
        Format {
            name: "material",
            seeds: {
                let mut seeds = seeds(&["2002834.toml", "1032930.toml", "tapered-cassette.toml"]);
                seeds.push(("own-sn-curve.toml".into(), own_sn_curve()));
                seeds
            },
            mutants: 90,
            focus: material_line,
            location: Location::Keyed(&[]),
            run: run_material,
        },
        Format {
            name: "sweep",
            seeds: seeds(&[
                "2002834/clearance-sweep.toml",
                "2002834/wear-life.toml",
                "2002834/fatigue-variants.toml",
                "2002834/rib-shape.toml",
            ]),
            mutants: 150,
            focus: any_line,
            location: Location::Keyed(&[]),
            run: run_sweep,
        },
        Format {
            name: "oil",
            seeds: seeds(&["oils/iso-vg68-mineral.toml", "oils/vg220-mineral.toml"]),
            mutants: 150,
            focus: any_line,
            location: Location::Keyed(&[]),
            run: run_oil,
        },
        Format {
            name: "journal",
            seeds: seeds(&["journal/seed002-ch4.toml"]),
            mutants: 60,
            focus: any_line,
            location: Location::Keyed(&[]),
            run: run_journal,
        },
        Format {
            name: "sn-curve",
            seeds: vec![(
                "sn.csv".into(),
                rolldyn_fatigue::sn::SnCurve::aisi_4340().to_csv_text(),
            )],
            mutants: 100,
            focus: any_line,
            location: Location::Table,
            run: run_sn_curve,
        },
        Format {
            name: "rainflow",
            seeds: vec![
                (
                    "history.csv".into(),
                    "stress\n-2\n1\n-3\n5\n-1\n3\n-4\n4\n-2\n7.5e7\n-3.2e8\n0\n".into(),
                ),
                (
                    "two-columns.csv".into(),
                    "t,stress\n0,1e8\n0.1,-2e8\n0.2,3e8\n0.3,-1e8\n0.4,2.5e8\n0.5,0\n".into(),
                ),
            ],
            mutants: 100,
            focus: any_line,
            location: Location::Table,
            run: run_rainflow,
        },
        Format {
            name: "cage-loads",
            seeds: vec![(
                "loads.json".into(),
                std::fs::read_to_string(cage_loads()).unwrap(),
            )],
            mutants: 80,
            focus: any_line,
            location: Location::Keyed(&[]),
            run: run_cage_loads,
        },
        Format {
            name: "cage-table",
            seeds: vec![("loads.parquet".into(), String::new())],
            mutants: 30,
            focus: any_line,
            location: Location::Table,
            run: run_cage_table,
        },
        Format {
            name: "wear-map",
            seeds: vec![("wear.csv".into(), wear_map())],
            mutants: 100,
            focus: any_line,
            location: Location::Table,
            run: run_wear_map,
        },
        Format {
            name: "designation",
            seeds: ["NU2215", "NJ 310", "NUP2308", "N 1012", "NU 2320"]
                .map(|d| (String::new(), d.to_string()))
                .to_vec(),
            mutants: 100,
            focus: any_line,
            location: Location::Value(&["designation", "type", "series", "bore"]),
            run: run_designation,
        },
        Format {
            name: "duty",
            seeds: [
                "time=0.3,speed=5000rpm,radial-load=15kN",
                "time=3,speed=4000rpm,radial-load=5kN;time=1,speed=8000rpm,radial-load=10kN,oil-temperature=90C",
                "time=1,axial-load=1kN,radial-load=8kN",
            ]
            .map(|d| (String::new(), d.to_string()))
            .to_vec(),
            mutants: 100,
            focus: any_line,
            location: Location::Value(&["--duty", "duty"]),
            run: run_duty,
        },
    ]
}

/// The wear-map mutant named by the model it is written beside (`model.toml` next to it).
fn run_wear_map(path: &str, index: usize) -> Outcome {
    let map = Path::new(path);
    let model = map.with_extension("toml");
    let text = example("2002834.toml").replace(
        "[outer_ring]",
        &format!(
            "[inner_ring.raceway_wear]\nfile = \"{}\"\n\n[outer_ring]",
            map.file_name().unwrap().to_string_lossy()
        ),
    );
    std::fs::write(&model, text).unwrap();
    run_model(&model.display().to_string(), index)
}

// ---------------------------------------------------------------------------------------------
// The test

/// The class of a mutant (the exit code) or the guarantee it broke.
enum Verdict {
    Exit(u8),
    Broken(String),
}

/// Runs `run` on `input` on its own thread; a panic or a run longer than [`HANG`] is broken.
fn judge(format: &Format, input: &str, index: usize, keys: &[String]) -> Verdict {
    let (send, receive) = mpsc::channel();
    let run = format.run;
    let owned = input.to_string();
    std::thread::spawn(move || {
        let _ = send.send(run(&owned, index));
    });
    match receive.recv_timeout(HANG) {
        Err(mpsc::RecvTimeoutError::Timeout) => Verdict::Broken(format!("hang (> {HANG:?})")),
        Err(mpsc::RecvTimeoutError::Disconnected) => Verdict::Broken("panicked".into()),
        Ok(Ok(found)) if found.is_empty() => Verdict::Exit(0),
        Ok(Ok(found)) => Verdict::Broken(format!(
            "exit 0 with non-finite numbers: {}",
            found.join(", ")
        )),
        Ok(Err(failure)) => {
            let message = failure.to_string();
            match failure {
                Failure::Input(_) if !located(&message, format.location, input, keys) => {
                    Verdict::Broken(format!("exit 2 without a location: {message}"))
                }
                Failure::Run(_) if message.trim().is_empty() => {
                    Verdict::Broken("exit 1 without a diagnosis".into())
                }
                _ => Verdict::Exit(failure.exit_code()),
            }
        }
    }
}

/// The column of an exit code in the classification table.
fn column(code: u8) -> usize {
    match code {
        0 => 0,
        2 => 1,
        _ => 2,
    }
}

#[test]
fn mutants_of_every_input_format_are_plausible_located_or_diagnosed() {
    let start = Instant::now();
    let dir = scratch();
    let mut table: BTreeMap<&str, [usize; 3]> = BTreeMap::new();
    let mut broken = Vec::new();
    let mut known_passing = Vec::new();
    for format in formats() {
        let counts = table.entry(format.name).or_default();
        // one generator per format: a changed seed file of one format leaves the others' mutants
        let mut rng = Rng::for_format(format.name);
        let keys: Vec<Vec<String>> = format.seeds.iter().map(|(_, t)| keys_of(t)).collect();
        for index in 0..format.mutants {
            let (file, seed) = &format.seeds[index % format.seeds.len()];
            let input = match format.location {
                Location::Table if file.ends_with(".parquet") => {
                    let bytes = std::fs::read(cage_loads().with_extension("parquet")).unwrap();
                    let (bytes, what) = if rng.below(2) == 0 {
                        let at = rng.below(bytes.len());
                        (bytes[..at].to_vec(), format!("truncated at byte {at}"))
                    } else {
                        let (b, n) = random_bytes(bytes, &mut rng);
                        (b, format!("{n} random bytes"))
                    };
                    let path = dir.join(format!("{}-{index}-{file}", format.name));
                    std::fs::write(&path, bytes).unwrap();
                    (path.display().to_string(), what)
                }
                Location::Keyed(_) | Location::Table => {
                    let (text, what) = mutate_file(seed, format.focus, &mut rng);
                    let path = dir.join(format!("{}-{index}-{file}", format.name));
                    std::fs::write(&path, &text).unwrap();
                    (path.display().to_string(), what)
                }
                Location::Value(_) => {
                    let (value, what) = mutate_value(seed, &mut rng);
                    (value.clone(), format!("{what}: '{value}'"))
                }
            };
            let (input, what) = input;
            let known = KNOWN_OPEN
                .iter()
                .find(|(f, i, _)| *f == format.name && *i == index);
            match (
                judge(&format, &input, index, &keys[index % keys.len()]),
                known,
            ) {
                (Verdict::Exit(code), None) => counts[column(code)] += 1,
                (Verdict::Exit(_), Some((_, _, defect))) => known_passing.push(format!(
                    "{} #{index} ({defect}) passes now: remove it from KNOWN_OPEN",
                    format.name
                )),
                (Verdict::Broken(why), None) => {
                    broken.push(format!("{} #{index} ({file}, {what}): {why}", format.name))
                }
                (Verdict::Broken(_), Some(_)) => {}
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    println!(
        "{:<12} {:>9} {:>9} {:>9}",
        "format", "exit 0", "exit 2", "exit 1"
    );
    for (name, [plausible, located, diagnosed]) in &table {
        println!("{name:<12} {plausible:>9} {located:>9} {diagnosed:>9}");
    }
    let total: usize = table.values().flatten().sum();
    println!(
        "{total} mutants classified, {} broken, {} known open, {:.1} s",
        broken.len(),
        KNOWN_OPEN.len(),
        start.elapsed().as_secs_f64()
    );
    broken.extend(known_passing);
    assert!(broken.is_empty(), "{}", broken.join("\n"));
    assert!(total + KNOWN_OPEN.len() >= 1000, "{total} mutants");
}

/// The location rule on messages of each kind.
#[test]
fn a_location_is_a_line_a_key_a_table_file_or_the_value() {
    let keys = keys_of("[cage]\nwidth = \"5 mm\"\n");
    let keyed = Location::Keyed(&[]);
    let file = "/tmp/m.toml";
    assert!(located(
        "/tmp/m.toml:2:1: cage.width — too wide",
        keyed,
        file,
        &keys
    ));
    assert!(located(
        "/tmp/m.toml: bad value at line 2",
        keyed,
        file,
        &keys
    ));
    assert!(located("cage.width must be positive", keyed, file, &keys));
    assert!(!located(
        "/tmp/m.toml: key with no value, expected `=`",
        keyed,
        file,
        &keys
    ));
    assert!(!located("cagewidth: no", keyed, file, &keys));
    assert!(located(
        "/tmp/h.csv: the file has no values",
        Location::Table,
        "/tmp/h.csv",
        &[]
    ));
    assert!(!located(
        "the file has no values",
        Location::Table,
        "/tmp/h.csv",
        &[]
    ));
    let value = Location::Value(&["--duty"]);
    assert!(located("'NU22X5': bad bore code", value, "NU22X5", &[]));
    assert!(located("--duty row 2: implausible", value, "time=1", &[]));
    assert!(!located("--speed: implausible", value, "time=1", &[]));
}

/// The walker reports a raw non-finite number by its path, and not one its level's
/// `non_finite` object explains.
#[test]
fn non_finite_numbers_are_found_unless_explained() {
    #[derive(Serialize)]
    struct Inner {
        a: f64,
        b: Option<f64>,
        non_finite: BTreeMap<&'static str, &'static str>,
    }
    #[derive(Serialize)]
    struct Outer {
        x: f64,
        inner: Vec<Inner>,
    }
    let value = Outer {
        x: f64::NAN,
        inner: vec![Inner {
            a: f64::INFINITY,
            b: Some(f64::NEG_INFINITY),
            non_finite: BTreeMap::from([("a", "unlimited")]),
        }],
    };
    assert_eq!(non_finite_numbers(&value), ["x = NaN", "inner.0.b = -inf"]);
}
