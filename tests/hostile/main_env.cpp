// One QCoreApplication for the campaign, as for the integration tests.
#include "../integration/main_env.cpp"
