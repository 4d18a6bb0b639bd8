// The integration tests drive Qt objects (timers, transports, QProcess) and need
// one QCoreApplication for the whole program. gtest_main owns main(), so the
// application lives in a global test environment, created before the first test
// and destroyed after the last.
#include <QCoreApplication>

#include <gtest/gtest.h>

#include <memory>

namespace {

class QtApplicationEnvironment final : public ::testing::Environment {
public:
    void SetUp() override
    {
        if (QCoreApplication::instance())
            return;
        m_app = std::make_unique<QCoreApplication>(m_argc, m_argv);
        QCoreApplication::setApplicationName(QStringLiteral("test_camera"));
    }
    void TearDown() override { m_app.reset(); }

private:
    // QCoreApplication keeps references to argc and argv: they must outlive it.
    int m_argc = 1;
    char m_name[12] = "test_camera";
    char* m_argv[2] = {m_name, nullptr};
    std::unique_ptr<QCoreApplication> m_app;
};

[[maybe_unused]] ::testing::Environment* const g_qtEnvironment =
    ::testing::AddGlobalTestEnvironment(new QtApplicationEnvironment);

} // namespace
