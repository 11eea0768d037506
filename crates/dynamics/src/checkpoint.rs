//! Byte serialisation of the full run state (state vector, integrator memory, accumulators) so
//! that a resumed run continues bit-for-bit. Little-endian; a tag with the format version
//! first, a checksum of everything before it last, and a fingerprint of the set-up (model,
//! operating conditions, settings) so that a checkpoint cannot be applied to another run.

use crate::error::DynError;

/// The frame of every checkpoint: the tag `RDYNCK` and the format version (09: the previous
/// Rosenbrock-W step size of the predictive controller; 08: the Rosenbrock-W factor step size
/// and bordered Jacobian; 07: the sliding-split maxima of the summary windows; 06: checksum,
/// output step, the caller's note).
const KIND: Kind = Kind {
    tag: b"RDYNCK",
    version: b"09",
};

pub(crate) use rolldyn_numerics::hash::fnv1a;
use rolldyn_numerics::sealed::{Kind, Unsealed};

/// Appends values to a byte buffer that starts with the tag and version.
#[derive(Debug)]
pub(crate) struct Writer {
    pub buf: Vec<u8>,
}

impl Writer {
    pub fn new() -> Self {
        Self { buf: KIND.header() }
    }
    /// The checkpoint: the buffer closed by its checksum.
    pub fn seal(self) -> Vec<u8> {
        KIND.seal(self.buf)
    }
    pub fn f64(&mut self, x: f64) {
        self.buf.extend_from_slice(&x.to_bits().to_le_bytes());
    }
    pub fn u64(&mut self, x: u64) {
        self.buf.extend_from_slice(&x.to_le_bytes());
    }
    /// Length-prefixed bytes.
    pub fn bytes(&mut self, b: &[u8]) {
        self.u64(b.len() as u64);
        self.buf.extend_from_slice(b);
    }
    pub fn slice(&mut self, v: &[f64]) {
        self.u64(v.len() as u64);
        for &x in v {
            self.f64(x);
        }
    }
}

/// Reads values back.
#[derive(Debug)]
pub(crate) struct Reader<'a> {
    pub buf: &'a [u8],
    pub pos: usize,
}

impl<'a> Reader<'a> {
    /// Reads a checkpoint written by [`Writer::seal`]: refuses another file, another format
    /// version and a checkpoint whose checksum does not match (a changed or cut byte).
    pub fn open(bytes: &'a [u8]) -> Result<Self, DynError> {
        let body = KIND.open(bytes).map_err(|e| {
            DynError::Checkpoint(match e {
                Unsealed::Foreign => "not a rolldyn dynamics checkpoint".into(),
                Unsealed::Version(found) => format!(
                    "format version {found}, this rolldyn reads version {} (written by another rolldyn: run again from the start)",
                    String::from_utf8_lossy(KIND.version)
                ),
                Unsealed::Damaged => e.to_string(),
            })
        })?;
        Ok(Self {
            buf: body,
            pos: KIND.header().len(),
        })
    }
    /// Whether every value has been read.
    pub fn at_end(&self) -> bool {
        self.pos == self.buf.len()
    }
    fn take8(&mut self) -> Result<[u8; 8], DynError> {
        let end = self.pos + 8;
        let s = self
            .buf
            .get(self.pos..end)
            .ok_or_else(|| DynError::Checkpoint("truncated data".into()))?;
        self.pos = end;
        let mut a = [0u8; 8];
        a.copy_from_slice(s);
        Ok(a)
    }
    pub fn f64(&mut self) -> Result<f64, DynError> {
        Ok(f64::from_bits(u64::from_le_bytes(self.take8()?)))
    }
    pub fn u64(&mut self) -> Result<u64, DynError> {
        Ok(u64::from_le_bytes(self.take8()?))
    }
    /// Bytes written by [`Writer::bytes`].
    pub fn bytes(&mut self) -> Result<Vec<u8>, DynError> {
        let n = self.u64()?;
        let end = usize::try_from(n)
            .ok()
            .and_then(|n| self.pos.checked_add(n))
            .filter(|&end| end <= self.buf.len())
            .ok_or_else(|| DynError::Checkpoint("truncated data".into()))?;
        let b = self.buf[self.pos..end].to_vec();
        self.pos = end;
        Ok(b)
    }
    pub fn slice_into(&mut self, v: &mut [f64]) -> Result<(), DynError> {
        let n = self.u64()? as usize;
        if n != v.len() {
            return Err(DynError::Checkpoint(format!(
                "vector of {n} values where {} are expected",
                v.len()
            )));
        }
        for x in v.iter_mut() {
            *x = self.f64()?;
        }
        Ok(())
    }
}
