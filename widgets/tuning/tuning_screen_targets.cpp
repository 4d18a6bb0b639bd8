// TuningScreen, its targets: the instruments it was given, the closed-loop axes their
// tuning() offers, the model plant, and why an instrument offers none.
#include "widgets/tuning/tuning_screen.h"

#include "device/jobs/tuning/tuning_runner.h"
#include "widgets/wording/wording.h"

#include <QComboBox>
#include <QLabel>

namespace ui {

void TuningScreen::renameInstrument(int index, const QString& name)
{
    for (Instrument& in : m_instruments)
        if (in.index == index)
            in.name = name;
    rebuildTargets();
    refreshReady();
}

void TuningScreen::addInstrument(int index, const QString& name, dev::Instrument* client)
{
    Instrument in;
    in.index = index;
    in.name = name;
    in.client = client;
    m_instruments.push_back(in);
    const int i = static_cast<int>(m_instruments.size()) - 1;
    connect(client, &dev::Instrument::stateChanged, this, [this](dev::LinkState) {
        rebuildTargets();
        refreshReady();
    });
    connect(client, &dev::Instrument::partsReplaced, this, [this, i] {
        watchTuning(i);
        rebuildTargets();
    });
    watchTuning(i);
    rebuildTargets();
}

void TuningScreen::watchTuning(int i)
{
    Instrument& in = m_instruments[i];
    disconnect(in.gainsWatch);
    in.tuning = in.client ? in.client->tuning() : nullptr;
    if (!in.tuning)
        return;
    in.gainsWatch = connect(in.tuning, &dev::TuningClient::gainsChanged, this, [this, i](int axis, const QString&) {
        const Choice* c = choice();
        if (!c || c->instrument != i || c->axis != axis)
            return;
        if (m_ownGainChanges > 0) {
            --m_ownGainChanges;  // our own Apply, already shown
            return;
        }
        if (!m_runner->busy())
            readGains();  // someone else (the CLI, a script) changed them: show what is in force
    });
}

QStringList TuningScreen::targetNames() const
{
    QStringList out;
    for (const auto& c : m_choices)
        out << c.name;
    return out;
}

const TuningScreen::Choice* TuningScreen::choice() const
{
    const int i = m_target->currentIndex();
    return i >= 0 && i < m_choices.size() ? &m_choices[i] : nullptr;
}

TuningScreen::Instrument* TuningScreen::instrumentOf(const Choice& c)
{
    return c.instrument >= 0 && c.instrument < m_instruments.size() ? &m_instruments[c.instrument] : nullptr;
}

QString TuningScreen::currentTarget() const { return choice() ? choice()->name : QString(); }

void TuningScreen::rebuildTargets()
{
    QList<Choice> next;
    QStringList unavailable;
    for (int i = 0; i < m_instruments.size(); ++i) {
        const Instrument& in = m_instruments[i];
        // An instrument once identified stays a choice while its link is down:
        // an interrupted job must be able to resume on the same target.
        if (!in.client || in.client->identity().axes.isEmpty())
            continue;
        if (!in.client->capabilities().testFlag(dev::Capability::PidGains))
            unavailable << QStringLiteral("%1: %2").arg(in.name, ui::words::text(in.client->whyNot(dev::Capability::PidGains)));
        if (!in.tuning)
            continue;
        for (int axis : in.tuning->tunableAxes())
            next.push_back({QStringLiteral("%1 %2").arg(in.name, QString(in.client->identity().axes[axis].letter)), i, axis});
    }
    next.push_back({tr("Model plant"), -1, -1});
    m_unavailable->setText(unavailable.join(QLatin1Char('\n')));
    m_unavailable->setVisible(!unavailable.isEmpty());
    // A target is an instrument's axis (or the model), not its name: the same targets under
    // new names (a language switch) are reworded in place, and the one chosen keeps its
    // gains, history, results and step tests.
    bool same = next.size() == m_choices.size();
    for (int i = 0; same && i < next.size(); ++i)
        same = next[i].instrument == m_choices[i].instrument && next[i].axis == m_choices[i].axis;
    if (same) {
        QSignalBlocker block(m_target);
        for (int i = 0; i < next.size(); ++i) {
            m_choices[i].name = next[i].name;
            if (m_target->itemText(i) != next[i].name)
                m_target->setItemText(i, next[i].name);
        }
        return;
    }
    if (m_runner->busy())
        return;  // the target list settles once the run has ended
    const QString was = m_targetPicked ? currentTarget() : m_savedTarget;
    m_choices = next;
    QSignalBlocker block(m_target);
    m_target->clear();
    for (const auto& c : m_choices)
        m_target->addItem(c.name);
    const int keep = m_target->findText(was);
    m_target->setCurrentIndex(keep >= 0 ? keep : 0);
    if (keep < 0 || was.isEmpty() || m_targetObj == nullptr)
        onTargetChosen();
    else if (const Choice* c = choice(); c && c->instrument >= 0 && m_instruments[c->instrument].client->isReady())
        readGains();  // back after a lost link: show what is in force now
}

bool TuningScreen::selectTarget(const QString& name)
{
    const int i = m_target->findText(name);
    if (i < 0 || m_runner->busy())
        return false;
    m_targetPicked = true;
    if (i == m_target->currentIndex())
        return true;
    m_target->setCurrentIndex(i);
    return true;
}

} // namespace ui
