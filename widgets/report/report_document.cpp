#include "widgets/report/report_document.h"

#include "widgets/report/accuracy_report.h"

#include <QCoreApplication>
#include <QFile>
#include <QPageLayout>
#include <QPageSize>

namespace ui::report {

Document::Document(const QString& path) : m_writer(path)
{
    m_writer.setPageSize(QPageSize(QPageSize::A4));
    m_writer.setPageMargins(QMarginsF(0, 0, 0, 0), QPageLayout::Millimeter);
    m_writer.setResolution(72);  // a device unit a point: fonts stay sane under the mm transform
    m_writer.setCreator(QStringLiteral("BenchPilot"));
    m_ok = m_painter.begin(&m_writer);
    if (m_ok)
        m_painter.scale(72.0 / 25.4, 72.0 / 25.4);
}

void Document::newPage()
{
    m_writer.newPage();
    ++m_page;
}

bool writeAtomically(const QString& pdfPath, const std::function<bool(const QString&)>& render, QString* error)
{
    if (!canRender()) {
        if (error)
            *error = QCoreApplication::translate("ui::report", "a PDF needs a graphical application object; none exists in this program");
        return false;
    }
    const QString temp = pdfPath + QStringLiteral(".part");
    QFile::remove(temp);
    auto fail = [&] {
        QFile::remove(temp);
        if (error)
            *error = QCoreApplication::translate("ui::report", "cannot write %1").arg(pdfPath);
        return false;
    };
    if (!render(temp))
        return fail();
    QFile::remove(pdfPath);
    if (!QFile::rename(temp, pdfPath))
        return fail();
    return true;
}

} // namespace ui::report
