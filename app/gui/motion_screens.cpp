#include "motion_screens.h"

#include "instrument_session.h"
#include "device/files/pattern_file.h"
#include "device/jobs/pattern_runner.h"
#include "widgets/joystick/joystick_screen.h"
#include "widgets/patterns/pattern_screen.h"

#include <QSettings>
#include <QTabWidget>

namespace app {

namespace {
const char* kKeys[2] = {"analyzer", "stage"};
}

MotionScreens::MotionScreens(InstrumentSession* const sessions[2], dev::tele::TelemetryHub* hub, const Hooks& hooks, QObject* parent)
    : QObject(parent)
{
    m_joyTabs = new QTabWidget;
    QVector<ui::PatternInstrument> instruments;
    for (int i = 0; i < 2; ++i) {
        dev::Instrument* c = hooks.instrument ? hooks.instrument(i) : sessions[i]->instrument();
        m_joystick[i] = new ui::JoystickScreen(c);
        if (hooks.warn)
            connect(m_joystick[i], &ui::JoystickScreen::problem, this, hooks.warn);
        m_joyTabs->addTab(m_joystick[i], sessions[i]->name());
        m_runners[i] = new dev::jobs::PatternRunner(c, this);
        instruments.push_back({sessions[i]->name(), c, m_runners[i], i});
    }
    connect(m_joyTabs, &QTabWidget::currentChanged, this, [this](int i) { m_joystick[i]->setFocus(); });
    m_patterns = new ui::PatternScreen(instruments, hub);
    if (hooks.confirm)
        m_patterns->setConfirm(hooks.confirm);
    if (hooks.confirmLongMove)
        m_patterns->setConfirmLongMove(hooks.confirmLongMove);
    if (hooks.chooseFile)
        m_patterns->setFileChooser(hooks.chooseFile);
    if (hooks.warn)
        connect(m_patterns, &ui::PatternScreen::problem, this, hooks.warn);
}

MotionScreens::~MotionScreens() = default;

void MotionScreens::showInstrument(int index)
{
    m_joyTabs->setCurrentIndex(index);
    m_patterns->setInstrument(index);
}

void MotionScreens::stopSticks()
{
    for (auto* j : m_joystick)
        j->stopAll();
}

void MotionScreens::load(QSettings& st)
{
    for (int i = 0; i < 2; ++i) {
        st.beginGroup(QStringLiteral("joystick/%1").arg(QLatin1String(kKeys[i])));
        ui::JoystickSettings s = m_joystick[i]->settings();
        s.maxSpeedMmS = st.value(QStringLiteral("maxSpeed"), i == 0 ? 20.0 : 5.0).toDouble();
        s.shaping.deadband = st.value(QStringLiteral("deadband"), s.shaping.deadband).toDouble();
        s.shaping.expo = st.value(QStringLiteral("expo"), s.shaping.expo).toDouble();
        m_joystick[i]->setSettings(s);
        st.endGroup();
    }
    // The last pattern as its file text: a pattern that no longer reads is simply not restored.
    const QString text = st.value(QStringLiteral("patterns/last")).toString();
    if (!text.isEmpty())
        if (auto r = dev::files::parsePattern(text.toStdString()); r.pattern)
            m_patterns->setPattern(*r.pattern);
    m_patterns->setInstrument(std::clamp(st.value(QStringLiteral("patterns/instrument"), 1).toInt(), 0, 1));
}

void MotionScreens::save(QSettings& st) const
{
    for (int i = 0; i < 2; ++i) {
        st.beginGroup(QStringLiteral("joystick/%1").arg(QLatin1String(kKeys[i])));
        const ui::JoystickSettings s = m_joystick[i]->settings();
        st.setValue(QStringLiteral("maxSpeed"), s.maxSpeedMmS);
        st.setValue(QStringLiteral("deadband"), s.shaping.deadband);
        st.setValue(QStringLiteral("expo"), s.shaping.expo);
        st.endGroup();
    }
    st.setValue(QStringLiteral("patterns/last"), QString::fromStdString(dev::files::writePattern(m_patterns->pattern())));
    st.setValue(QStringLiteral("patterns/instrument"), m_patterns->instrument());
}

} // namespace app
