/* stub: to be written */
typedef int acbb_stub_sim;
