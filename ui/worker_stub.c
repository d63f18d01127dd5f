/* stub */
typedef int acbb_stub_worker;
