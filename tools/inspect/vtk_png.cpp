#include "vtk_png.hpp"

#include <fmt/format.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkWindowToImageFilter.h>

#include "tidewater/detail/atomic_sibling.hpp"

namespace tidewater::inspect {

Status save_window_png(vtkRenderWindow* window, const std::filesystem::path& png) {
    window->Render();
    vtkNew<vtkWindowToImageFilter> capture;
    capture->SetInput(window);
    capture->ReadFrontBufferOff();
    capture->Update();
    detail::sweep_stale_siblings(png);
    const std::filesystem::path temp = detail::temporary_sibling(png);
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(temp.c_str());
    writer->SetInputConnection(capture->GetOutputPort());
    writer->Write();
    std::error_code ec;
    if (writer->GetErrorCode() == 0 && std::filesystem::exists(temp, ec)) {
        std::filesystem::rename(temp, png, ec);
        if (!ec) return {};
    }
    std::filesystem::remove(temp, ec);
    return Error{ErrorCode::io_error, fmt::format("{}: cannot write the picture", png.string())};
}

}  // namespace tidewater::inspect
