"""The parts of scripts/sweep-report: reading and merging sweep folders (sweeps), Pareto fronts
(fronts), label placement (labels), the plots (plot_common, plot_error, plot_heatmap,
plot_params) and the HTML page (page, page_runs, page_assets)."""
