"""The code of scripts/independent-campaigns.py (the entry point: arguments and the run).

Independent blind campaigns for `gearloss diagnose`, one module per stage:
  numerics     interpolation, root finding, mean/median, small minimisers (standard library only)
  cases        the case variants, the keys read from case and oil files, the derived case
  model_table  the binary's fixed-temperature maps, interpolated in oil temperature
  heat_balance the heat path re-implemented here, the steady oil temperature, its checks
  effects      the concealed effects in perturbed forms, and the acceptance mapping
  forms        the model-form axes, a case's forms, derived cases with another form or oil
  campaigns    a case's shared setup, the plan, one campaign's recordings.csv + truth.json
  identifiability whether a pair's two effects can be told from one of them refitted alone
  multi_oil    multi-oil campaigns: per-oil model tables, per-oil effects, the `oil` column
  synth_own    issue 38: campaigns from `gearloss synth` itself (confidence when it is earned)
  robustness   issue 38: row order (three orderings; a drift with a `run` column) and outliers
  outside_model issue 38: outside the library, the final model's residual and the recovered form
  scoring      diagnose run blind, the outcome of each campaign
  tables       scores.md's tables, failures.md, each category's headline numbers
  proof_doc    docs/diagnosis-proof.md (targets, per-category and per-case tables)
Split from the single script to keep every file under the project's 600-line limit.
"""
