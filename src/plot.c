/* stub: to be written (plot helper) */
typedef int acbb_stub_plot;
