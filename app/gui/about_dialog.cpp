#include "about_dialog.h"

#include "app/common/version_text.h"

#include <QDialogButtonBox>
#include <QEvent>
#include <QLabel>
#include <QVBoxLayout>
#include <QtGlobal>

#include <Eigen/Core>
#include <qcustomplot.h>

namespace app {

namespace {
QString eigenVersion()
{
    return QStringLiteral("%1.%2.%3").arg(EIGEN_WORLD_VERSION).arg(EIGEN_MAJOR_VERSION).arg(EIGEN_MINOR_VERSION);
}
} // namespace

AboutDialog::AboutDialog(QWidget* parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("aboutBenchPilot"));
    auto* layout = new QVBoxLayout(this);
    m_text = new QLabel;
    m_text->setTextFormat(Qt::RichText);
    m_text->setWordWrap(true);
    m_text->setOpenExternalLinks(true);
    m_text->setTextInteractionFlags(Qt::TextBrowserInteraction);
    m_text->setMinimumWidth(460);
    layout->addWidget(m_text);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    layout->addWidget(buttons);
    retranslateUi();
}

QString AboutDialog::text()
{
    // Library names and licence identifiers stay as their authors write them.
    const QString row = QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td></tr>");
#ifdef BP_WITH_WEBSOCKETS
    const QString qtModules = QStringLiteral("Qt 6 (Core, Gui, Widgets, Network, SerialPort, PrintSupport, WebSockets)");
#else
    const QString qtModules = QStringLiteral("Qt 6 (Core, Gui, Widgets, Network, SerialPort, PrintSupport)");
#endif
    const QString rows = row.arg(qtModules, QString::fromLatin1(qVersion()), QStringLiteral("LGPL-3.0-only OR GPL-2.0-only OR GPL-3.0-only"))
        + row.arg(QStringLiteral("QCustomPlot"), QStringLiteral(QCUSTOMPLOT_VERSION_STR), QStringLiteral("GPL-3.0-or-later"))
        + row.arg(QStringLiteral("Eigen"), eigenVersion(), QStringLiteral("MPL-2.0"));
    return QStringLiteral("<h3>BenchPilot %1</h3>").arg(QStringLiteral(BP_VERSION))
        + QStringLiteral("<p>%1</p>").arg(tr("Operator and test-bench application for laboratory motion instruments."))
        + QStringLiteral("<p>%1</p>").arg(tr("Built with Qt %1, running on Qt %2.").arg(QStringLiteral(QT_VERSION_STR), QString::fromLatin1(qVersion())))
        + QStringLiteral("<p>%1<br>%2</p>")
              .arg(tr("Copyright © 2026 The BenchPilot authors."),
                   tr("BenchPilot is free software: you can redistribute it and modify it under the terms of the GNU General "
                      "Public License, version 3 or (at your option) any later version (%1). It comes with NO WARRANTY, to "
                      "the extent permitted by law. The full text: %2.")
                       .arg(QString::fromLatin1(kLicenceSpdx),
                            QStringLiteral("<a href=\"https://www.gnu.org/licenses/gpl-3.0.html\">gnu.org/licenses/gpl-3.0</a>")))
        + QStringLiteral("<p>%1</p>").arg(tr("Libraries it is made of:"))
        + QStringLiteral("<table cellspacing=\"4\"><tr><th align=\"left\">%1</th><th align=\"left\">%2</th><th align=\"left\">%3</th></tr>%4</table>")
              .arg(tr("Library"), tr("Version"), tr("Licence"), rows);
}

void AboutDialog::retranslateUi()
{
    setWindowTitle(tr("About BenchPilot"));
    m_text->setText(text());
}

void AboutDialog::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QDialog::changeEvent(event);
}

HelpMenu::HelpMenu(QWidget* parent) : QMenu(parent)
{
    m_about = addAction(QString());
    m_about->setMenuRole(QAction::AboutRole);
    connect(m_about, &QAction::triggered, this, [this] {
        // One box at a time; a second click brings it forward.
        QWidget* window = parentWidget() ? parentWidget()->window() : nullptr;
        auto* box = window ? window->findChild<AboutDialog*>() : nullptr;
        if (!box) {
            box = new AboutDialog(window);
            box->setAttribute(Qt::WA_DeleteOnClose);
        }
        box->show();
        box->raise();
        box->activateWindow();
    });
    retranslateUi();
}

void HelpMenu::retranslateUi()
{
    setTitle(tr("&Help"));
    m_about->setText(tr("&About BenchPilot…"));
}

void HelpMenu::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QMenu::changeEvent(event);
}

} // namespace app
