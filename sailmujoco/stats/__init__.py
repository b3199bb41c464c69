"""Statistics over seeds: every interval, paired difference, pass count and verdict the reports
print (:mod:`.intervals`, on :mod:`scipy.stats`)."""

from .intervals import (
                        CONFIDENCE,
                        VERDICT_RULE,
                        Interval,
                        mean_interval,
                        paired_difference,
                        paired_ratio,
                        pass_rate,
                        unpaired_difference,
                        verdict,
)

__all__ = ["CONFIDENCE", "VERDICT_RULE", "Interval", "mean_interval", "paired_difference",
           "paired_ratio", "pass_rate", "unpaired_difference", "verdict"]
