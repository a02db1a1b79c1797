"""The parts of scripts/sweep-report: reading and merging sweep folders (sweeps), Pareto fronts
(fronts), label placement (labels), the plots (plots, plot_common) and the HTML page (page, page_assets)."""
