// One QApplication for every GUI test in this program (gtest_main owns main()).
#include <QApplication>

#include <gtest/gtest.h>

namespace {
class QtGuiEnvironment : public ::testing::Environment {
public:
    void SetUp() override
    {
        if (!QApplication::instance()) {
            static int argc = 1;
            static char name[] = "test_gui";
            static char* argv[] = {name, nullptr};
            m_app = new QApplication(argc, argv);
            QApplication::setOrganizationName(QStringLiteral("BenchPilotTests"));
        }
    }
    void TearDown() override
    {
        delete m_app;
        m_app = nullptr;
    }

private:
    QApplication* m_app = nullptr;
};
[[maybe_unused]] ::testing::Environment* const g_env = ::testing::AddGlobalTestEnvironment(new QtGuiEnvironment);
} // namespace
