//! Ranges of quantities for parameter sweeps: `"1500rpm..4500rpm:500rpm"`.

use crate::dimension::Dim;
use crate::quantity::{Quantity, UnitError, parse_difference_si};
use std::str::FromStr;

/// A single value, a list, or an inclusive, evenly stepped, ascending range `start..end:step`.
#[derive(Debug, Clone, PartialEq)]
pub struct QuantityRange<D: Dim> {
    pub values: Vec<Quantity<D>>,
}

impl<D: Dim> QuantityRange<D> {
    /// True when the text named one value, not a range.
    pub fn is_single(&self) -> bool {
        self.values.len() == 1
    }
}

impl<D: Dim> FromStr for QuantityRange<D> {
    type Err = UnitError;

    /// Parses `value`, `start..end:step` (start ≤ end, step > 0) or a comma list `a,b,c`.
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        if let Some((start, rest)) = text.split_once("..") {
            let (end, step) = rest.split_once(':').ok_or_else(|| UnitError::BadNumber {
                text: format!("{text} (a range needs a step: start..end:step)"),
            })?;
            let start = Quantity::<D>::parse(start)?.si();
            let end = Quantity::<D>::parse(end)?.si();
            let step = parse_difference_si(step, D::DIMENSION)?;
            let refuse = |reason| {
                Err(UnitError::BadRange {
                    text: text.to_string(),
                    reason,
                })
            };
            if end < start {
                return refuse(
                    "the range runs backwards: write it from the smaller to the larger value",
                );
            }
            if step <= 0.0 {
                return refuse("the step must be positive");
            }
            if (end - start) / step > 1.0e6 {
                return refuse("the step gives more than 1e6 points");
            }
            let count = ((end - start) / step + 1e-9).floor() as usize;
            let values = (0..=count)
                .map(|k| Quantity::from_si(start + step * k as f64))
                .collect();
            return Ok(Self { values });
        }
        let values = text
            .split(',')
            .map(Quantity::<D>::parse)
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Self { values })
    }
}
