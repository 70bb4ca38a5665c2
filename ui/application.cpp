#include "ui/application.h"

#include <QApplication>
#include <QIcon>

namespace fieldsight::ui {

QString applicationId()
{
    return QStringLiteral(FIELDSIGHT_APP_ID);
}

void identifyApplication()
{
    QApplication::setOrganizationName(QStringLiteral("Fieldsight"));
    QApplication::setApplicationName(QStringLiteral("fieldsight"));
    QApplication::setApplicationDisplayName(QStringLiteral("Fieldsight"));
    QApplication::setDesktopFileName(applicationId());
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/%1.svg").arg(applicationId())));
}

} // namespace fieldsight::ui
