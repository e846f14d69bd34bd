# Precompiled headers: every translation unit of a target parses the same Qt (and GoogleTest)
# headers first, about half its compile time at -O2. CI builds the whole tree twice on two cores
# (the suite, then under ASan), so this is where its time goes. Only headers that every module of
# the kind may include: no Widgets in the core set (model and transport stay without them).
option(OPENTOP_PCH "Precompile the Qt and GoogleTest headers each target includes" ON)

set(OPENTOP_PCH_CORE
    <QByteArray> <QDateTime> <QHash> <QList> <QMap> <QObject> <QPointer> <QSet> <QString>
    <QStringList> <QTimer> <QVariant> <QVector> <algorithm> <functional> <memory> <optional>
    <vector>)
set(OPENTOP_PCH_WIDGETS
    ${OPENTOP_PCH_CORE} <QAbstractItemModel> <QComboBox> <QHBoxLayout> <QLabel> <QLineEdit>
    <QPushButton> <QVBoxLayout> <QWidget>)

# opentop_pch(target CORE|WIDGETS [extra headers...])
function(opentop_pch target kind)
    if(NOT OPENTOP_PCH)
        return()
    endif()
    target_precompile_headers(${target} PRIVATE ${OPENTOP_PCH_${kind}} ${ARGN})
endfunction()
